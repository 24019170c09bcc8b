#pragma once
// Text that is safe to print on one line and to put in JSON: file names and messages may hold
// bytes that are not UTF-8 (a file name is any bytes but '/' and NUL) or line breaks.

#include <string>
#include <string_view>

namespace gfield {

/// `text` with every byte that is not part of a valid UTF-8 sequence written as \xNN, and control
/// characters as \n, \r, \t or \xNN: valid UTF-8 without line breaks, so one line of output and a
/// string nlohmann::json can dump. Valid UTF-8 text without control characters comes back as is.
std::string printable(std::string_view text);

/// The shortest decimal text ("%.{1..9}g") that strtof reads back as exactly `value` (0.005f is
/// "0.005", not "0.00499999989"): numbers printed for a command line that must give them back.
std::string float_text(float value);

/// The same for a double ("%.{1..17}g" that strtod reads back): a value in a message that must
/// differ visibly from the bound it broke (1000000.4 is "1000000.4", not "1e+06").
std::string double_text(double value);

}  // namespace gfield

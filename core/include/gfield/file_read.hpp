#pragma once
// Reading a whole input file into memory, with its size checked first.

#include <cstdint>
#include <string>

namespace gfield {

/// Reads all of `filename` into `data`. False with a one-line "FILE: problem" when the file does
/// not exist, is not a regular file, cannot be opened or read, is empty, or holds more than
/// `max_bytes` bytes (nothing is allocated then).
bool read_file(const std::string& filename, std::uint64_t max_bytes, std::string& data,
               std::string& error);

}  // namespace gfield

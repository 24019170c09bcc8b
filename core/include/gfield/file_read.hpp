#pragma once
// Reading a whole input file into memory, with its size checked first.

#include <cstdint>
#include <string>

namespace gfield {

/// Why `filename` cannot be read as a file, "" when it is a regular file (or a link to one): "no
/// such file", "a symbolic link loop", "a dangling symbolic link", "a FIFO, not a regular file",
/// "a folder, not a file", "not a regular file" (a socket or a device), or the system's reason.
std::string file_problem(const std::string& filename);

/// Reads all of `filename` into `data`. False with a one-line "FILE: problem" when the file does
/// not exist, is not a regular file, cannot be opened or read, is empty, or holds more than
/// `max_bytes` bytes (nothing is allocated then).
bool read_file(const std::string& filename, std::uint64_t max_bytes, std::string& data,
               std::string& error);

}  // namespace gfield

#pragma once
// Reading inputs safely: only regular files of bounded size; missing files, directories, devices,
// FIFOs, binary data, BOM and CRLF.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fl::spectral {

// The largest input file read: 64 MiB (64 · 2^20 bytes). The largest refractiveindex.info page is
// about 2.6 MB, an OCIO config a few kB, an environment map of 8192 × 4096 half-float RGB 200 MB
// uncompressed but far less as a compressed EXR.
inline constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{64} << 20;

// The one check of every input file (text, YAML, OCIO config, EXR) before it is opened: InputError
// naming the path unless it is a regular file of at most `max_bytes`. Only stat(2) is used, so a
// FIFO without a writer is refused without blocking and a device such as /dev/zero is never read.
void check_input_file(const std::string& path, std::uintmax_t max_bytes = kMaxInputBytes);

// The file's bytes, after check_input_file: opened without blocking and checked again on the open
// file (the path may have changed in between), at most `max_bytes` of it read.
std::string read_input_bytes(const std::string& path, std::uintmax_t max_bytes = kMaxInputBytes);

// Every entry of the folder `dir` (the paths, sorted). InputError naming the folder when it does
// not exist ("<what> not found"), is not a folder or cannot be listed (permissions).
std::vector<std::string> list_folder(const std::string& dir, const std::string& what);

// The whole file as UTF-8 text with a leading byte-order mark removed and CRLF / CR turned into
// LF. Throws InputError for what check_input_file refuses, an unreadable or empty file, or binary
// content (NUL bytes or invalid control characters).
std::string read_text_file(const std::string& path);

// Splits on '\n' (the text is already normalized).
std::vector<std::string_view> split_lines(std::string_view text);

// Splits on any run of the given delimiter characters, dropping empty fields.
std::vector<std::string_view> split_fields(std::string_view line, std::string_view delimiters);
// The same fields, the first out.size() of them into `out` (a data row's, without a vector per
// row); returns how many fields the line has.
size_t split_fields(std::string_view line, std::string_view delimiters,
                    std::span<std::string_view> out);

// The whole field (trimmed) as a decimal number, correctly rounded (std::from_chars; an optional
// leading '+'); false when it is not a finite number. Denormals, and values below them that round
// to zero, are numbers; overflow is not. Not locale-dependent: the decimal mark is '.'.
bool parse_finite(std::string_view field, double& value);

std::string_view trim(std::string_view s);

}  // namespace fl::spectral

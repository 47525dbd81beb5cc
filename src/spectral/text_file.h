#pragma once
// Reading small text inputs safely: missing files, directories, binary data, BOM and CRLF.
#include <string>
#include <string_view>
#include <vector>

namespace fl::spectral {

// The whole file as UTF-8 text with a leading byte-order mark removed and CRLF / CR turned into
// LF. Throws InputError for a missing file, a directory, an unreadable or empty file, or binary
// content (NUL bytes or invalid control characters).
std::string read_text_file(const std::string& path);

// Splits on '\n' (the text is already normalized).
std::vector<std::string_view> split_lines(std::string_view text);

// Splits on any run of the given delimiter characters, dropping empty fields.
std::vector<std::string_view> split_fields(std::string_view line, std::string_view delimiters);

// strtod over the whole field; false when the field is not a finite number. Denormals (strtod's
// underflow) are numbers.
bool parse_finite(std::string_view field, double& value);

std::string_view trim(std::string_view s);

}  // namespace fl::spectral

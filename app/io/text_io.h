// Text files (reports: JUnit XML, JSON, HTML) written the way images are:
// to a hidden temporary beside the target, flushed to disk, read back and
// compared, then renamed into place. A reader never sees half a report and
// a failed write leaves nothing behind.
//
//   write_text_file("out/junit.xml", xml);   // throws ms::Error on failure
#pragma once
#include <filesystem>
#include <string>

namespace ms {

// Throws bad_input (key `key`) when the directory is missing or not
// writable or the path is a directory; system for I/O errors (a full disk).
void write_text_file(const std::filesystem::path& path, const std::string& text, const std::string& key = "-o");

}  // namespace ms

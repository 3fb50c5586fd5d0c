// `marchstudio test --report DIR`: one self-contained HTML page,
// DIR/index.html, with each case's reference, result and difference heat
// map side by side, its metrics and budgets, failures first. The images are
// PNG files next to the page; it needs no server, no network and no script
// (a few lines of inline script only mark an image that did not load).
#pragma once
#include <filesystem>

#include "suite/suite.h"
#include "suite/suite_run.h"
#include "io/image.h"

namespace ms {

// Writes DIR/<case>.reference.png, .result.png and .diff.png (those it can:
// no reference, no diff) as display images and records their names in `r`.
// `reference` may be empty (missing); `result` is the render as stored.
void write_case_images(const std::filesystem::path& dir, CaseResult& r, const Image& reference, const Image& result);

// The page; image paths are the names write_case_images() recorded.
std::string suite_html(const Suite& suite, const SuiteResult& r);

// DIR/index.html, atomically.
void write_html_report(const std::filesystem::path& dir, const Suite& suite, const SuiteResult& r);

}  // namespace ms

// What `marchstudio test` reports: a line per case for the terminal, the
// results as JSON (schema "marchstudio.test/1", docs/testing.md) and as
// JUnit XML for GitLab, GitHub and Jenkins. Text in, text out; the HTML
// page is suite/suite_html.h.
#pragma once
#include <string>

#include "suite/suite.h"
#include "suite/suite_run.h"

namespace ms {

inline constexpr const char* kTestSchema = "marchstudio.test/1";

// %.6g; "inf" and "nan" spelt out.
std::string format_value(double v);
// One check, e.g. "psnr 41.20 dB >= 40.00 dB", "max 0.0314 (8.01/255) > 0.02 (5.10/255) at frame 3".
std::string check_text(const CheckResult& r);
// "pass", "WARN", "FAIL", "ERROR": how the terminal shows an outcome.
const char* outcome_label(Outcome o);

// "FAIL  seed.egl  psnr 35.20 dB < 40.00 dB  (0.41 s)", no newline.
std::string case_line(const CaseResult& r);
// "12 cases: 10 passed, 1 warned, 1 failed, 0 could not run (12.3 s)".
std::string summary_line(const SuiteResult& r);

std::string suite_json(const Suite& suite, const SuiteResult& r);   // pretty-printed, ends in a newline
std::string suite_junit(const Suite& suite, const SuiteResult& r);  // XML, ends in a newline

// Text made safe for XML and HTML element content and attribute values;
// characters XML 1.0 cannot hold are dropped.
std::string xml_escape(const std::string& text);

}  // namespace ms

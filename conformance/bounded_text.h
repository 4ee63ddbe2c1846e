// bounded_text.h — what vgc keeps of text that is not its own (an
// implementation's answer, a line of a user's file) when it copies it into
// a message, a report or a counterexample file: at most a few KiB, and the
// whole size said.
//
// Spec: none (CI practice; issue 31, item 5: an implementation that
// answered `rejected <50 MB of A>` made 500 MB of stdout, of summary.md,
// report.html, report.json and junit.xml each, and 3.4 GB of vgc's memory).
//
// Rationale: a run's outputs and vgc's memory must stay bounded whatever
// the implementation sends. The cut is made where the text comes in (the
// exec adapter's answer lines, a baseline's reasons), so every copy made
// afterwards is bounded too; it says how much there was, so a reader knows
// that something was cut and how big it was.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vgc {

// How much of one piece of foreign text is kept: 4 KiB.
inline constexpr std::size_t kShownBytes = 4096;

// `s` itself when it has at most `limit` bytes; otherwise its first `limit`
// bytes (cut before an incomplete UTF-8 sequence), then
// "… (52,428,800 bytes, first 4 KiB shown)".
std::string bounded_text(std::string_view s, std::size_t limit = kShownBytes);

// "52,428,800": a byte count with thousands separators.
std::string grouped_count(std::size_t n);

}  // namespace vgc

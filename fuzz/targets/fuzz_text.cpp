// fuzz_text.cpp — the text command parser on arbitrary bytes.
//
// Spec: reference/node/command_text.h (the text form; parse(print(c)) is
// bit-identical to c) and number_text.h (exact number forms).
//
// Per input: parse_commands never crashes; an error names a line within the
// input and a column >= 1. Whatever parsed (the whole file, or the lines
// before the error) is printed; the printed text parses again, to commands
// bit_equal to the first parse, and printing those gives the same text
// (print is a fixpoint of parse . print).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "command_text.h"
#include "report_finding.h"

namespace {
constexpr const char* kTarget = "fuzz_text";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace vgc;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<Command> first;
  TextError error;
  const bool ok = parse_commands(text, &first, &error);
  if (!ok) {
    const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
    if (error.line < 1 || error.line > lines || error.column < 1)
      fuzz::report_finding(kTarget, "parse error at line " + std::to_string(error.line) + ", column " +
                                        std::to_string(error.column) + " outside the input", first);
    if (error.message.empty()) fuzz::report_finding(kTarget, "parse error without a message", first);
  }
  const std::string printed = print_commands(first);
  std::vector<Command> second;
  TextError error2;
  if (!parse_commands(printed, &second, &error2))
    fuzz::report_finding(kTarget, "printed commands do not parse: " + error2.to_string(), first);
  if (second.size() != first.size())
    fuzz::report_finding(kTarget, "printed commands parse to a different count", first);
  for (std::size_t i = 0; i < first.size(); ++i)
    if (!bit_equal(first[i], second[i]))
      fuzz::report_finding(kTarget, "command " + std::to_string(i + 1) + " changed in print/parse: " +
                                        print_command(second[i]), first);
  if (print_commands(second) != printed)
    fuzz::report_finding(kTarget, "print(parse(print(x))) differs from print(x)", first);
  return 0;
}

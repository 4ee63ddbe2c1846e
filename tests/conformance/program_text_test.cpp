// program_text_test.cpp — the directives of a counterexample file
// (conformance/program_text.h): "#! history KIND", "#! mesh" and
// "#! capability ..." print and parse back to the same Program, and a
// malformed, repeated or misplaced one is an error naming its line and
// column (docs/commands.md section 1, docs/certify.md "Replaying a failure").
#include <gtest/gtest.h>

#include "program_text.h"

namespace vgc {
namespace {

constexpr const char* kCommands =
    "vertex_set_xyz_real64 0 0 0 0 0\n"
    "vertex_set_xyz_real64 0 1 1 0 0\n";

TEST(ProgramText, DirectivesRoundTrip) {
  Program p;
  TextError error;
  ASSERT_TRUE(parse_program(kCommands, &p, &error)) << error.to_string();
  p.history_kind = FindingKind::Timeout;
  p.mesh = true;
  p.request = CapabilityRequest{"subdivision", 2, std::nullopt};
  const std::string text = print_program(p);
  EXPECT_NE(text.find("\n#! mesh\n#! capability subdivision variant 2\n"), std::string::npos) << text;
  Program back;
  ASSERT_TRUE(parse_program(text, &back, &error)) << error.to_string() << "\n" << text;
  EXPECT_EQ(back.commands.size(), 2u);
  EXPECT_EQ(back.history_kind, FindingKind::Timeout);
  EXPECT_NE(text.find("#! history timeout\n"), std::string::npos) << text;
  EXPECT_TRUE(back.mesh);
  ASSERT_TRUE(back.request.has_value());
  EXPECT_EQ(back.request->capability, "subdivision");
  EXPECT_EQ(back.request->variant, 2);
  // A program without the directive is not a mesh (parse resets it).
  ASSERT_TRUE(parse_program(kCommands, &back, &error));
  EXPECT_FALSE(back.mesh);
  EXPECT_FALSE(back.history_kind.has_value());
  EXPECT_FALSE(back.request.has_value());
}

struct Malformed {
  const char* text;
  std::size_t line, column;
  const char* says;
};

TEST(ProgramText, MalformedMeshDirectivesNameTheirLine) {
  const Malformed cases[] = {
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! mesh now\n", 2, 9, "alone on its line"},
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! mesh\n#! mesh\n", 3, 1, "a second mesh directive"},
      {"#! mesh\nvertex_set_xyz_real64 0 0 0 0 0\n", 1, 1, "must follow the last command (line 2)"},
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! history tired\n", 2, 12, "KIND one of"},
      // The variant and the drawn number are read exactly (std::from_chars).
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! capability subdivision variant -1\n", 2, 35, "the variant number"},
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! capability subdivision variant 2x\n", 2, 35, "the variant number"},
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! capability edits variant 1 draw 4294967296\n", 2, 36,
       "the drawn number"},
      {"vertex_set_xyz_real64 0 0 0 0 0\n#! capability edits variant 1 draw +5\n", 2, 36, "the drawn number"},
  };
  for (const Malformed& m : cases) {
    Program p;
    TextError error;
    EXPECT_FALSE(parse_program(m.text, &p, &error)) << m.text;
    EXPECT_EQ(error.line, m.line) << m.text << error.to_string();
    EXPECT_EQ(error.column, m.column) << m.text << error.to_string();
    EXPECT_NE(error.message.find(m.says), std::string::npos) << m.text << error.to_string();
  }
}

}  // namespace
}  // namespace vgc

// command_text_test.cpp — the text form of commands (reference/node/command_text.cpp):
// bit-exact round trips, the printed forms of numbers and names, error
// positions and messages, comments, blank lines, CRLF, and robustness
// against arbitrary bytes.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

#include "arbitrary_command.h"
#include "command_text.h"
#include "test_util.h"

namespace vgc {
namespace {

using test::C;

std::uint64_t bits(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}
double from_bits(std::uint64_t b) {
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d;
}

// ---- round trips -----------------------------------------------------------------

RC_GTEST_PROP(CommandTextProperty, ParseCommandLineOfPrintIsBitEqual, (Command c)) {
  const std::string line = print_command(c);
  RC_ASSERT(line.find('\n') == std::string::npos);
  Command back;
  bool blank = true;
  TextError e;
  RC_ASSERT(parse_command_line(line, 7, &back, &blank, &e));
  RC_ASSERT(!blank);
  RC_ASSERT(bit_equal(c, back));
}

RC_GTEST_PROP(CommandTextProperty, ParseCommandsOfPrintCommandsIsBitEqual, (std::vector<Command> cs)) {
  const std::string text = print_commands(cs);
  std::vector<Command> back;
  std::vector<std::size_t> lines;
  TextError e;
  RC_ASSERT(parse_commands(text, &back, &e, &lines));
  RC_ASSERT(back.size() == cs.size());
  for (std::size_t i = 0; i < cs.size(); ++i) {
    RC_ASSERT(bit_equal(cs[i], back[i]));
    RC_ASSERT(lines[i] == i + 1);
  }
}

RC_GTEST_PROP(CommandTextProperty, RoundTripSurvivesCrlfCommentsAndExtraBlanks, (Command c)) {
  std::string line = print_command(c);
  // Widen every separator (outside quotes the printer puts exactly one space).
  std::string wide = "\t ";
  bool in_quote = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (in_quote) {
      wide += ch;
      if (ch == '\\' && i + 1 < line.size()) wide += line[++i];
      else if (ch == '"') in_quote = false;
    } else if (ch == '"') {
      wide += ch;
      in_quote = true;
    } else {
      wide += ch == ' ' ? std::string(" \t ") : std::string(1, ch);
    }
  }
  const std::string text = "# header\r\n\r\n" + wide + " # trailing \"comment\r\n";
  std::vector<Command> back;
  TextError e;
  RC_ASSERT(parse_commands(text, &back, &e));
  RC_ASSERT(back.size() == 1u);
  RC_ASSERT(bit_equal(c, back[0]));
}

// ---- printed forms -----------------------------------------------------------------

TEST(CommandText, PrintsSpecialRealsInTheirExactForms) {
  cmd::VertexSetXyzReal64 c{0, 1, std::numeric_limits<double>::quiet_NaN(), -0.0, INFINITY};
  EXPECT_EQ(print_command(c), "vertex_set_xyz_real64 0 1 nan -0 inf");
  c = {0, 1, from_bits(0x7FF0000000000001ull), from_bits(0xFFF8000000000000ull), -INFINITY};
  EXPECT_EQ(print_command(c), "vertex_set_xyz_real64 0 1 nan(0x7FF0000000000001) nan(0xFFF8000000000000) -inf");
  c = {0, 1, 0.1, DBL_MAX, std::numeric_limits<double>::denorm_min()};
  EXPECT_EQ(print_command(c), "vertex_set_xyz_real64 0 1 0.1 1.7976931348623157e+308 5e-324");
  cmd::VertexSetXyzReal32 f{0, 1, FLT_MAX, 0.1f, std::numeric_limits<float>::quiet_NaN()};
  EXPECT_EQ(print_command(f), "vertex_set_xyz_real32 0 1 3.4028235e+38 0.1 nan");
  f = {0, 1, -0.0f, std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::quiet_NaN()};
  EXPECT_EQ(print_command(f), "vertex_set_xyz_real32 0 1 -0 1e-45 nan(0xFFC00000)");
}

TEST(CommandText, PrintsAllOnesOfEachWidthInHexAndEverythingElseInDecimal) {
  EXPECT_EQ(print_command(cmd::VertexSetXyzReal64{0xFFFF, 0xFFFFFFFF, 0, 0, 0}),
            "vertex_set_xyz_real64 0xFFFF 0xFFFFFFFF 0 0 0");
  EXPECT_EQ(print_command(cmd::VertexSetUint32{65535, 65535, 4294967294u}), "vertex_set_uint32 0xFFFF 65535 4294967294");
  EXPECT_EQ(print_command(cmd::PolygonSetFaceUint8{2, 255, 255}), "polygon_set_face_uint8 2 255 0xFF");
  EXPECT_EQ(print_command(cmd::PolygonSetCornerUint32{1, 0, {0, 1, 2, 0xFFFFFFFF}}),
            "polygon_set_corner_uint32 1 0 0 1 2 0xFFFFFFFF");
}

TEST(CommandText, PrintsLayerTypesAndRealFormatsByNameWhenValidAndAsNumbersOtherwise) {
  EXPECT_EQ(print_command(cmd::LayerCreate{2, "uv", 2, 0, 0.5}), "layer_create 2 \"uv\" VERTEX_REAL 0 0.5");
  EXPECT_EQ(print_command(cmd::LayerCreate{2, "a", 130, 1, 0}), "layer_create 2 \"a\" POLYGON_FACE_UINT8 1 0");
  EXPECT_EQ(print_command(cmd::LayerCreate{2, "a", 3, 0, 0}), "layer_create 2 \"a\" 3 0 0");
  EXPECT_EQ(print_command(cmd::LayerCreate{2, "a", 255, 0, 0}), "layer_create 2 \"a\" 0xFF 0 0");
  EXPECT_EQ(print_command(cmd::LayerSubscribe{3, 0}), "layer_subscribe 3 REAL32");
  EXPECT_EQ(print_command(cmd::LayerSubscribe{3, 1}), "layer_subscribe 3 REAL64");
  EXPECT_EQ(print_command(cmd::LayerSubscribe{3, 2}), "layer_subscribe 3 2");
  // Both spellings parse.
  Command c = C("layer_create 2 \"a\" 130 1 0");
  EXPECT_EQ(std::get<cmd::LayerCreate>(c).type, 130);
  c = C("layer_subscribe 3 1");
  EXPECT_EQ(std::get<cmd::LayerSubscribe>(c).real_format, 1);
}

TEST(CommandText, PrintsBoneFieldsInWireOrder) {
  cmd::BoneCreate b;
  b.bone_id = 3;
  b.weight = "w";
  b.reference = "";
  b.parent = 0xFFFF;
  b.pos = {1, 2, 3};
  b.pos_label = "px";
  b.rot = {0, 0, 0.5, -1};
  b.rot_label = "rx";
  EXPECT_EQ(print_command(b), "bone_create 3 \"w\" \"\" 0xFFFF 1 2 3 \"px\" 0 0 0.5 -1 \"rx\"");
}

TEST(CommandText, QuotesNamesEscapingQuoteBackslashAndEveryNonPrintableByte) {
  cmd::CreaseSetVertex c{std::string("a\"b\\c\n\0\x7F\xFF~ #", 12), 0};
  EXPECT_EQ(print_command(c), "crease_set_vertex \"a\\\"b\\\\c\\x0A\\x00\\x7F\\xFF~ #\" 0");
  const Command back = C(print_command(c));
  EXPECT_EQ(std::get<cmd::CreaseSetVertex>(back).layer, c.layer);
  // Lower-case hex digits are accepted too; '#' inside quotes is not a comment.
  EXPECT_EQ(std::get<cmd::CreaseSetVertex>(C("crease_set_vertex \"\\x0a\\xfF#x\" 0")).layer, "\n\xFF#x");
}

TEST(CommandText, ParsesNanSpellingsToTheirBits) {
  auto x_of = [](const char* line) { return bits(std::get<cmd::VertexSetXyzReal64>(C(line)).x); };
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 nan 0 0"), 0x7FF8000000000000ull);
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 -nan 0 0"), 0xFFF8000000000000ull);
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 nan(0x7FF0000000000001) 0 0"), 0x7FF0000000000001ull);
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 -nan(0x7FF0000000000001) 0 0"), 0xFFF0000000000001ull);
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 -0 0 0"), 0x8000000000000000ull);
  EXPECT_EQ(x_of("vertex_set_xyz_real64 0 0 0x1p-1074 0 0"), 0x0000000000000001ull);
  auto f_of = [](const char* line) {
    const float f = std::get<cmd::VertexSetReal32>(C(line)).value;
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
  };
  EXPECT_EQ(f_of("vertex_set_real32 2 0 nan"), 0x7FC00000u);
  EXPECT_EQ(f_of("vertex_set_real32 2 0 nan(0x7F800001)"), 0x7F800001u);
  EXPECT_EQ(f_of("vertex_set_real32 2 0 -inf"), 0xFF800000u);
}

// ---- errors ---------------------------------------------------------------------------

struct ErrorCase {
  std::string line;
  std::size_t column;
  std::string message;  // exact
};

TEST(CommandText, MalformedLinesReportLineColumnAndWhatWasExpected) {
  const ErrorCase cases[] = {
      {"vertex_frobnicate 1", 1,
       "expected a command verb (layer_create, vertex_set_xyz_real64, ...), found \"vertex_frobnicate\""},
      {"  \tVertex_delete 1", 4,
       "expected a command verb (layer_create, vertex_set_xyz_real64, ...), found \"Vertex_delete\""},
      {"  vertex_delete", 16, "expected vertex_id (uint32), found end of line"},
      {"vertex_delete # no id", 15, "expected vertex_id (uint32), found end of line"},
      {"vertex_delete 1 2", 17, "expected end of line after vertex_delete, found \"2\""},
      {"vertex_set_xyz_real64 0 0 1 2 x", 31, "expected z (real64), found \"x\""},
      {"vertex_set_xyz_real32 0 0 1 2 1e39", 31, "expected z (real32), found \"1e39\""},
      {"vertex_set_xyz_real64 0 0 1 2 +3", 31, "expected z (real64), found \"+3\""},
      {"vertex_set_xyz_real64 0 0 1 2 NaN", 31, "expected z (real64), found \"NaN\""},
      {"vertex_set_xyz_real64 0 0 1 2 nan(0x1)", 31, "expected z (real64), found \"nan(0x1)\""},
      {"vertex_set_xyz_real64 0 0 1 2 -nan(0xFFF8000000000000)", 31,
       "expected z (real64), found \"-nan(0xFFF8000000000000)\""},
      {"layer_subscribe 65536 REAL32", 17, "expected layer_id (uint16), found \"65536\""},
      {"layer_subscribe 1 REAL16", 19, "expected real_format (real format (REAL32, REAL64 or 0..255)), found \"REAL16\""},
      {"layer_create 2 \"a\" VERTEX_FLOAT 0 0", 20,
       "expected type (layer type (VERTEX_XYZ ... POLYGON_FACE_REAL or 0..255)), found \"VERTEX_FLOAT\""},
      {"layer_create 2 \"a\" 256 0 0", 20,
       "expected type (layer type (VERTEX_XYZ ... POLYGON_FACE_REAL or 0..255)), found \"256\""},
      {"polygon_set_face_uint8 2 0 256", 28, "expected value (uint8), found \"256\""},
      {"vertex_set_uint32 2 0 4294967296", 23, "expected value (uint32), found \"4294967296\""},
      {"vertex_set_uint32 2 0 -1", 23, "expected value (uint32), found \"-1\""},
      {"polygon_set_corner_uint32 1 0 0 1 2", 36, "expected v[3] (uint32), found end of line"},
      {"bone_create 1 \"w\" \"\" 0 1 2 \"\" 0 0 0 1 \"\"", 28, "expected pos[2] (real64), found \"\"\"\""},
      {"crease_set_vertex abc 0", 19, "expected layer (quoted name), found \"abc\""},
      {"layer_create 2 \"uv VERTEX_REAL 0 0", 35,
       "bad quoted name: use \\\" \\\\ or \\xHH escapes and close the quote on the same line"},
      {"crease_set_edge \"a\\qb\" 0", 19,
       "bad quoted layer: use \\\" \\\\ or \\xHH escapes and close the quote on the same line"},
      {"crease_set_edge \"a\\x4\" 0", 19,
       "bad quoted layer: use \\\" \\\\ or \\xHH escapes and close the quote on the same line"},
      {"crease_set_edge \"a\tb\" 0", 19,
       "bad quoted layer: use \\\" \\\\ or \\xHH escapes and close the quote on the same line"},
      {"crease_set_edge \"ab\"0", 21, "expected a blank after the closing quote of layer, found \"0\""},
  };
  for (const auto& ec : cases) {
    Command c;
    bool blank = true;
    TextError e;
    EXPECT_FALSE(parse_command_line(ec.line, 12, &c, &blank, &e)) << ec.line;
    EXPECT_FALSE(blank) << ec.line;
    EXPECT_EQ(e.line, 12u) << ec.line;
    EXPECT_EQ(e.column, ec.column) << ec.line;
    EXPECT_EQ(e.message, ec.message) << ec.line;
  }
}

TEST(CommandText, ErrorToStringNamesLineAndColumn) {
  TextError e{3, 24, "expected x"};
  EXPECT_EQ(e.to_string(), "line 3, column 24: expected x");
}

TEST(CommandText, ParseCommandsStopsAtTheFirstBadLineAndKeepsTheCommandsBeforeIt) {
  const std::string text = "# cube start\n\nvertex_delete 1\n   \nvertex_delete 2 3\nvertex_delete 4\n";
  std::vector<Command> out;
  TextError e;
  EXPECT_FALSE(parse_commands(text, &out, &e));
  EXPECT_EQ(e.line, 5u);
  EXPECT_EQ(e.column, 17u);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(std::get<cmd::VertexDelete>(out[0]).vertex_id, 1u);
}

TEST(CommandText, CommentsAndBlankLinesAreSkippedAndLineNumbersCountThem) {
  const std::string text =
      "# a comment\n"
      "\n"
      "   \t  \n"
      "vertex_delete 3 # trailing comment\n"
      "\t# indented comment\n"
      "vertex_delete 4#glued comment\n"
      "crease_set_vertex \"#not a comment\" 5";  // no final newline
  std::vector<Command> out;
  std::vector<std::size_t> lines;
  TextError e;
  ASSERT_TRUE(parse_commands(text, &out, &e, &lines)) << e.to_string();
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(lines, (std::vector<std::size_t>{4, 6, 7}));
  EXPECT_EQ(std::get<cmd::VertexDelete>(out[1]).vertex_id, 4u);
  EXPECT_EQ(std::get<cmd::CreaseSetVertex>(out[2]).layer, "#not a comment");
  Command c;
  bool blank = false;
  EXPECT_FALSE(parse_command_line("  # only a comment", 1, &c, &blank, &e));
  EXPECT_TRUE(blank);
  EXPECT_FALSE(parse_command_line("", 1, &c, &blank, &e));
  EXPECT_TRUE(blank);
}

TEST(CommandText, CrlfLineEndingsParseLikeLf) {
  const std::string text = "vertex_delete 3\r\n\r\ncrease_set_edge \"e\" 0xFFFFFFFF\r\n# c\r\n";
  std::vector<Command> out;
  std::vector<std::size_t> lines;
  TextError e;
  ASSERT_TRUE(parse_commands(text, &out, &e, &lines)) << e.to_string();
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(lines, (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(std::get<cmd::CreaseSetEdge>(out[1]).layer, "e");
  EXPECT_EQ(std::get<cmd::CreaseSetEdge>(out[1]).def_crease, 0xFFFFFFFFu);
  // An error on a CRLF line is still reported at the right place.
  EXPECT_FALSE(parse_commands("vertex_delete\r\n", &out, &e));
  EXPECT_EQ(e.line, 1u);
  EXPECT_EQ(e.column, 15u);
}

// ---- robustness ---------------------------------------------------------------------

void check_any_text(const std::string& text) {
  std::vector<Command> out;
  std::vector<std::size_t> lines;
  TextError e;
  if (parse_commands(text, &out, &e, &lines)) {
    // Whatever parsed prints and parses back to the same commands.
    std::vector<Command> again;
    RC_ASSERT(parse_commands(print_commands(out), &again, &e));
    RC_ASSERT(again.size() == out.size());
    for (std::size_t i = 0; i < out.size(); ++i) RC_ASSERT(bit_equal(out[i], again[i]));
  } else {
    RC_ASSERT(e.line >= 1);
    RC_ASSERT(e.column >= 1);
    RC_ASSERT(!e.message.empty());
    RC_ASSERT(e.message.rfind("expected", 0) == 0 || e.message.rfind("bad quoted", 0) == 0);
  }
}

RC_GTEST_PROP(CommandTextProperty, ArbitraryBytesNeverCrashAndErrorsArePositioned, (std::string text)) {
  check_any_text(text);
}

// Bytes that look like commands: verbs, numbers, quotes and separators mixed,
// so that parsing gets past the verb.
RC_GTEST_PROP(CommandTextProperty, CommandLikeNoiseNeverCrashes, ()) {
  const auto piece = rc::gen::weightedOneOf<std::string>({
      {3, rc::gen::element<std::string>("layer_create", "vertex_set_xyz_real64", "polygon_set_corner_uint32",
                                        "bone_create", "crease_set_edge", "vertex_delete", "layer_subscribe")},
      {4, rc::gen::element<std::string>(" ", " ", "\t", "\n", "\r\n", "#", "\"", "\\", "\\x", "(", ")")},
      {4, rc::gen::element<std::string>("0", "1", "0xFFFF", "0xFFFFFFFF", "-0", "nan", "-nan", "nan(0x",
                                        "inf", "1e308", "0x1p3", "REAL32", "VERTEX_REAL", "65536", "\"w\"")},
      {1, rc::gen::arbitrary<std::string>()},
  });
  const auto pieces = *rc::gen::container<std::vector<std::string>>(piece);
  std::string text;
  for (const auto& p : pieces) text += p;
  check_any_text(text);
}

}  // namespace
}  // namespace vgc

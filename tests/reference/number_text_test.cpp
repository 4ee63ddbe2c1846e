// number_text_test.cpp — exact number and name forms (reference/node/number_text.cpp).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

#include "arbitrary_command.h"
#include "number_text.h"

namespace vgc {
namespace {

template <class F, class B> B bits_of(F f) {
  B b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}
double d_bits(std::uint64_t b) { return gen::bits_to<double>(b); }
float f_bits(std::uint32_t b) { return gen::bits_to<float>(b); }

TEST(NumberText, FormatsFiniteDoublesInTheShortestRoundTripDecimal) {
  EXPECT_EQ(format_f64(0.0), "0");
  EXPECT_EQ(format_f64(-0.0), "-0");
  EXPECT_EQ(format_f64(1.0), "1");
  EXPECT_EQ(format_f64(-1.5), "-1.5");
  EXPECT_EQ(format_f64(0.1), "0.1");
  EXPECT_EQ(format_f64(1e300), "1e+300");
  EXPECT_EQ(format_f64(DBL_MAX), "1.7976931348623157e+308");
  EXPECT_EQ(format_f64(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(format_f64(double(0.1f)), "0.10000000149011612");
}

TEST(NumberText, FormatsNonFiniteDoublesAsInfOrNanWithFullBits) {
  EXPECT_EQ(format_f64(INFINITY), "inf");
  EXPECT_EQ(format_f64(-INFINITY), "-inf");
  EXPECT_EQ(format_f64(d_bits(0x7FF8000000000000ull)), "nan");
  EXPECT_EQ(format_f64(d_bits(0xFFF8000000000000ull)), "nan(0xFFF8000000000000)");
  EXPECT_EQ(format_f64(d_bits(0x7FF0000000000001ull)), "nan(0x7FF0000000000001)");
  EXPECT_EQ(format_f64(d_bits(0x7FFFFFFFFFFFFFFFull)), "nan(0x7FFFFFFFFFFFFFFF)");
}

TEST(NumberText, FormatsFloatsAtFloatPrecision) {
  EXPECT_EQ(format_f32(0.1f), "0.1");
  EXPECT_EQ(format_f32(-0.0f), "-0");
  EXPECT_EQ(format_f32(FLT_MAX), "3.4028235e+38");
  EXPECT_EQ(format_f32(std::numeric_limits<float>::denorm_min()), "1e-45");
  EXPECT_EQ(format_f32(f_bits(0x7FC00000u)), "nan");
  EXPECT_EQ(format_f32(f_bits(0xFFC00000u)), "nan(0xFFC00000)");
  EXPECT_EQ(format_f32(f_bits(0x7F800001u)), "nan(0x7F800001)");
  EXPECT_EQ(format_f32(-INFINITY), "-inf");
}

TEST(NumberText, FormatsTheAllOnesValueOfEachWidthInUpperCaseHex) {
  EXPECT_EQ(format_uint(0xFFFFFFFFu, 32), "0xFFFFFFFF");
  EXPECT_EQ(format_uint(0xFFFFu, 32), "65535");
  EXPECT_EQ(format_uint(0xFFFFu, 16), "0xFFFF");
  EXPECT_EQ(format_uint(0xFFu, 16), "255");
  EXPECT_EQ(format_uint(0xFFu, 8), "0xFF");
  EXPECT_EQ(format_uint(0, 8), "0");
  EXPECT_EQ(format_uint(4294967294u, 32), "4294967294");
}

TEST(NumberText, ParsesDecimalHexFloatInfAndNanSpellings) {
  double d = 7;
  ASSERT_TRUE(parse_f64("-0", &d));
  EXPECT_EQ((bits_of<double, std::uint64_t>(d)), 0x8000000000000000ull);
  ASSERT_TRUE(parse_f64("1e-3", &d));
  EXPECT_EQ(d, 0.001);
  ASSERT_TRUE(parse_f64(".5", &d));
  EXPECT_EQ(d, 0.5);
  ASSERT_TRUE(parse_f64("0x1.8p1", &d));
  EXPECT_EQ(d, 3.0);
  ASSERT_TRUE(parse_f64("-0x1p-1074", &d));
  EXPECT_EQ((bits_of<double, std::uint64_t>(d)), 0x8000000000000001ull);
  ASSERT_TRUE(parse_f64("inf", &d));
  EXPECT_EQ(d, INFINITY);
  ASSERT_TRUE(parse_f64("-nan", &d));
  EXPECT_EQ((bits_of<double, std::uint64_t>(d)), 0xFFF8000000000000ull);
  ASSERT_TRUE(parse_f64("nan(0x7ff0000000000002)", &d));
  EXPECT_EQ((bits_of<double, std::uint64_t>(d)), 0x7FF0000000000002ull);
  float f = 7;
  ASSERT_TRUE(parse_f32("nan(0xFFC00001)", &f));
  EXPECT_EQ((bits_of<float, std::uint32_t>(f)), 0xFFC00001u);
  ASSERT_TRUE(parse_f32("3.4028235e+38", &f));
  EXPECT_EQ(f, FLT_MAX);
}

TEST(NumberText, RejectsEverythingElseWithoutTouchingTheOutput) {
  const char* bad64[] = {"",      " 1",      "1 ",       "+1",         "1e400",     "--1",         "Inf",
                         "INF",   "infinity", "NaN",      "nan()",      "nan(0x1)",  "nan(0x7FF0000000000000)",
                         "-nan(0xFFF8000000000000)",      "nan(0x1FFF8000000000000)", "0x", "1.2.3",
                         "1e",    "e5",       "0x-1p3",   "-0x-1p3",    "0x+1p3",    "1,5",          "١"};
  for (const char* s : bad64) {
    double d = 42;
    EXPECT_FALSE(parse_f64(s, &d)) << s;
    EXPECT_EQ(d, 42.0) << s;
  }
  const char* bad32[] = {"1e39", "-1e39", "nan(0x7FF8000000000000)", "nan(0x7F800000)", "inff"};
  for (const char* s : bad32) {
    float f = 42;
    EXPECT_FALSE(parse_f32(s, &f)) << s;
    EXPECT_EQ(f, 42.0f) << s;
  }
}

TEST(NumberText, ParsesUnsignedIntegersWithinTheFieldWidthOnly) {
  std::uint32_t u = 0;
  ASSERT_TRUE(parse_uint("0xFFFFFFFF", 32, &u));
  EXPECT_EQ(u, 0xFFFFFFFFu);
  ASSERT_TRUE(parse_uint("0X1f", 32, &u));
  EXPECT_EQ(u, 31u);
  ASSERT_TRUE(parse_uint("007", 8, &u));
  EXPECT_EQ(u, 7u);
  ASSERT_TRUE(parse_uint("65535", 16, &u));
  EXPECT_EQ(u, 65535u);
  ASSERT_TRUE(parse_uint("255", 8, &u));
  const std::pair<const char*, int> bad[] = {{"4294967296", 32}, {"65536", 16}, {"256", 8}, {"0x100", 8},
                                             {"-1", 32},         {"+1", 32},    {"", 32},   {"0x", 32},
                                             {" 1", 32},         {"1 ", 32},    {"1.0", 32}, {"0x+1", 32},
                                             {"1e3", 32},        {"0b1", 32}};
  for (const auto& [s, w] : bad) {
    u = 99;
    EXPECT_FALSE(parse_uint(s, w, &u)) << s;
    EXPECT_EQ(u, 99u) << s;
  }
}

TEST(NumberText, QuotesAndUnquotesNames) {
  EXPECT_EQ(format_quoted(""), "\"\"");
  EXPECT_EQ(format_quoted("uv map"), "\"uv map\"");
  EXPECT_EQ(format_quoted(std::string("\"\\\0\n\x1F\x7F\x80", 7)), "\"\\\"\\\\\\x00\\x0A\\x1F\\x7F\\x80\"");
  std::string out;
  std::size_t used = 0, at = 0;
  ASSERT_TRUE(parse_quoted("\"a\\\"b\" rest", &out, &used, &at));
  EXPECT_EQ(out, "a\"b");
  EXPECT_EQ(used, 6u);
  // Failures and where they are.
  EXPECT_FALSE(parse_quoted("abc", &out, &used, &at));
  EXPECT_EQ(at, 0u);
  EXPECT_FALSE(parse_quoted("\"abc", &out, &used, &at));
  EXPECT_EQ(at, 4u);
  EXPECT_FALSE(parse_quoted("\"a\\n\"", &out, &used, &at));
  EXPECT_EQ(at, 2u);
  EXPECT_FALSE(parse_quoted("\"ab\\x4g\"", &out, &used, &at));
  EXPECT_EQ(at, 3u);
  EXPECT_FALSE(parse_quoted("\"ab\\", &out, &used, &at));
  EXPECT_EQ(at, 4u);
  EXPECT_FALSE(parse_quoted("\"a\nb\"", &out, &used, &at));
  EXPECT_EQ(at, 2u);
}

RC_GTEST_PROP(NumberTextProperty, F64RoundTripsBitExactly, ()) {
  const double d = *gen::gen_f64_any();
  double back = 0;
  RC_ASSERT(parse_f64(format_f64(d), &back));
  RC_ASSERT((bits_of<double, std::uint64_t>(back)) == (bits_of<double, std::uint64_t>(d)));
}

RC_GTEST_PROP(NumberTextProperty, F32RoundTripsBitExactly, ()) {
  const float f = *gen::gen_f32_any();
  float back = 0;
  RC_ASSERT(parse_f32(format_f32(f), &back));
  RC_ASSERT((bits_of<float, std::uint32_t>(back)) == (bits_of<float, std::uint32_t>(f)));
}

RC_GTEST_PROP(NumberTextProperty, UintRoundTripsAtEveryWidth, (std::uint32_t v)) {
  for (int w : {8, 16, 32}) {
    const std::uint32_t x = w == 32 ? v : v & ((1u << w) - 1u);
    std::uint32_t back = ~x;
    RC_ASSERT(parse_uint(format_uint(x, w), w, &back));
    RC_ASSERT(back == x);
  }
}

RC_GTEST_PROP(NumberTextProperty, QuotedNamesRoundTripAndArePrintableAscii, ()) {
  const std::string name = *gen::gen_name();
  const std::string q = format_quoted(name);
  for (unsigned char c : q) RC_ASSERT(c >= 0x20 && c < 0x7F);
  std::string back;
  std::size_t used = 0, at = 0;
  RC_ASSERT(parse_quoted(q + " tail", &back, &used, &at));
  RC_ASSERT(back == name);
  RC_ASSERT(used == q.size());
}

}  // namespace
}  // namespace vgc

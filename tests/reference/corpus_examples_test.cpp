// corpus_examples_test.cpp — every command file in corpora/examples/ parses,
// and each command gives the result its line's comment announces: a comment
// that starts with a reason name (e.g. "# BASE_LAYER") expects that
// rejection, any other line expects OK.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_util.h"

namespace vgc {
namespace {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The first word of the comment on `line` (outside quotes), or "".
std::string comment_word(const std::string& line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (quoted && line[i] == '\\') { ++i; continue; }
    if (line[i] == '"') quoted = !quoted;
    if (!quoted && line[i] == '#') {
      std::istringstream rest(line.substr(i + 1));
      std::string w;
      rest >> w;
      while (!w.empty() && (w.back() == ':' || w.back() == ',')) w.pop_back();
      return w;
    }
  }
  return "";
}

TEST(CorpusExamples, EveryExampleParsesAndEachCommandGivesTheAnnouncedResult) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(VGC_SOURCE_DIR "/corpora/examples")) {
    if (entry.path().extension() != ".vgc") continue;
    ++files;
    const std::string text = read_file(entry.path());
    std::vector<Command> cs;
    std::vector<std::size_t> lines;
    TextError e;
    ASSERT_TRUE(parse_commands(text, &cs, &e, &lines)) << entry.path() << ": " << e.to_string();
    std::vector<std::string> raw;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) raw.push_back(l);
    Node n;
    int rejected = 0;
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const std::string before = print_snapshot(n);
      const Reason got = n.apply(cs[i]);
      Reason expected = Reason::Ok;
      parse_reason_name(comment_word(raw[lines[i] - 1]), &expected);
      EXPECT_EQ(reason_name(got), reason_name(expected)) << entry.path().filename() << " line " << lines[i];
      if (got != Reason::Ok) {
        ++rejected;
        EXPECT_EQ(print_snapshot(n), before);
      }
    }
    EXPECT_GE(cs.size(), 10u) << entry.path();
    (void)rejected;
  }
  EXPECT_GE(files, 5);
}

}  // namespace
}  // namespace vgc

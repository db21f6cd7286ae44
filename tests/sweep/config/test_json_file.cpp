// Strict JSON reading: positions of syntax errors, duplicate keys, overflowing numbers.
#include "sweep/config/json_file.hpp"

#include <gtest/gtest.h>

#include "sweep/errors.hpp"

namespace wirepack::sweep {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_json_text(text, "f.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(JsonFile, ParsesValidText) {
  const auto j = parse_json_text(R"({"a": [1, {"b": 2.5}], "c": "x"})", "f.json");
  EXPECT_EQ(j["a"][1]["b"], 2.5);
  EXPECT_EQ(j["c"], "x");
}

TEST(JsonFile, SyntaxErrorHasLineAndColumn) {
  EXPECT_EQ(error_of("{\"a\": 1,\n \"b\": }").rfind("f.json: line 2, column 7: syntax error", 0),
            0u)
      << error_of("{\"a\": 1,\n \"b\": }");
  EXPECT_NE(error_of("").find("f.json: line 1, column 1"), std::string::npos);
}

TEST(JsonFile, DuplicateKeysNamed) {
  EXPECT_EQ(error_of(R"({"a": {"b": 1, "b": 2}})"), "f.json: /a/b: duplicate key");
  std::vector<std::string> soft;
  const auto j = parse_json_text(R"({"a": 1, "a": 2})", "f.json", &soft);
  ASSERT_EQ(soft.size(), 1u);
  EXPECT_EQ(j["a"], 2);
}

TEST(JsonFile, OverflowNamed) {
  EXPECT_NE(error_of(R"({"a": {"b": -1e999}})").find("f.json: /a/b: must be a finite number"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"a": [0, 1, 1e400]})").find("f.json: /a/2: must be a finite number"),
            std::string::npos)
      << error_of(R"({"a": [0, 1, 1e400]})");
}

TEST(JsonFile, PointerEscaping) {
  EXPECT_EQ(pointer_child("/x", "a/b~c"), "/x/a~1b~0c");
}

}  // namespace
}  // namespace wirepack::sweep

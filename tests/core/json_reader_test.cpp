// core/json_reader.h: values as written, and one located error for each kind of malformed input.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/json_reader.h"

namespace rc {
namespace {

TEST(JsonReader, ReadsValues) {
  const JsonValue v = parseJson("{\"a\": [1, -2.5e1, true, null],\n \"b\": {\"c\": \"x\\\"y\"}}", "t.json");
  ASSERT_TRUE(v.isObject());
  const JsonValue* a = v.find("a");
  ASSERT_TRUE(a && a->isArray());
  ASSERT_EQ(a->array.size(), 4u);
  EXPECT_EQ(a->array[1].number, -25.0);
  EXPECT_TRUE(a->array[2].boolean);
  EXPECT_EQ(v.find("b")->find("c")->string, "x\"y");
  EXPECT_EQ(v.find("b")->line, 2);
  EXPECT_EQ(v.find("missing"), nullptr);
}

TEST(JsonReader, ErrorsNameSourceAndLine) {
  auto message = [](const std::string& text) {
    try {
      parseJson(text, "t.json");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("{\"a\": 1,\n\"a\": 2}"), "t.json:2: member 'a' given twice");
  EXPECT_EQ(message("[1, 2\n"), "t.json:2: expected ']'");
  EXPECT_EQ(message("[1] x"), "t.json:1: unexpected text after the JSON value");
  EXPECT_EQ(message("[1e999]"), "t.json:1: expected a value, got '1e999'");
  EXPECT_EQ(message("\"abc"), "t.json:1: unterminated string");
  EXPECT_EQ(message(std::string(100, '[')), "t.json:1: nesting deeper than 64");
  EXPECT_EQ(message(""), "t.json:1: unexpected end of input");
}

}  // namespace
}  // namespace rc

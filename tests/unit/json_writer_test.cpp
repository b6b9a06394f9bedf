// json_writer_test.cpp — the --stats-json writer: exact text for escaping, nesting and numbers.
#include "common/json_writer.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "common/errors.h"

namespace vkpt::json_writer_test {
namespace {

std::string compact(void (*write)(JsonWriter&)) {
    std::ostringstream out;
    JsonWriter json(out, 0);
    write(json);
    EXPECT_TRUE(json.complete());
    return out.str();
}

std::string compactDouble(double value) {
    std::ostringstream out;
    JsonWriter(out, 0).value(value);
    return out.str();
}

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(jsonQuoted("plain"), "\"plain\"");
    EXPECT_EQ(jsonQuoted("say \"hi\""), "\"say \\\"hi\\\"\"");
    EXPECT_EQ(jsonQuoted("C:\\scenes\\box.gltf"), "\"C:\\\\scenes\\\\box.gltf\"");
    EXPECT_EQ(jsonQuoted("a\nb\tc\rd\be\ff"), "\"a\\nb\\tc\\rd\\be\\ff\"");
    EXPECT_EQ(jsonQuoted(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
    EXPECT_EQ(jsonQuoted(std::string("nul\0byte", 8)), "\"nul\\u0000byte\"");
    EXPECT_EQ(jsonQuoted("/ stays"), "\"/ stays\"");
}

TEST(JsonWriter, PassesUtf8Through) {
    EXPECT_EQ(jsonQuoted("Stéfan → 100 µm"), "\"Stéfan → 100 µm\"");
}

TEST(JsonWriter, WritesNestedObjectsAndArraysCompactly) {
    const std::string text = compact([](JsonWriter& json) {
        json.beginObject()
            .field("scene", "cornell.gltf")
            .key("size")
            .beginArray()
            .value(64)
            .value(48u)
            .endArray()
            .key("timing")
            .beginObject()
            .field("seconds", 1.5)
            .field("converged", true)
            .key("note")
            .null()
            .endObject()
            .key("empty")
            .beginArray()
            .endArray()
            .key("none")
            .beginObject()
            .endObject()
            .endObject();
    });
    EXPECT_EQ(text, R"({"scene":"cornell.gltf","size":[64,48],"timing":{"seconds":1.5,)"
                    R"("converged":true,"note":null},"empty":[],"none":{}})");
}

TEST(JsonWriter, IndentsEachMemberOnItsOwnLine) {
    std::ostringstream out;
    JsonWriter json(out, 2);
    json.beginObject().field("a", 1).key("b").beginArray().value(2).value(3).endArray().key("c");
    json.beginArray().endArray().endObject();
    EXPECT_EQ(out.str(), "{\n  \"a\": 1,\n  \"b\": [\n    2,\n    3\n  ],\n  \"c\": []\n}");
}

TEST(JsonWriter, WritesIntegersExactlyAtTheirLimits) {
    const std::string text = compact([](JsonWriter& json) {
        json.beginArray()
            .value(std::numeric_limits<std::int64_t>::min())
            .value(std::numeric_limits<std::uint64_t>::max())
            .value(std::int8_t(-7))
            .value(std::uint16_t(65535))
            .value(false)
            .endArray();
    });
    EXPECT_EQ(text, "[-9223372036854775808,18446744073709551615,-7,65535,false]");
}

TEST(JsonWriter, WritesDoublesAsShortestRoundTrip) {
    EXPECT_EQ(compactDouble(0.1), "0.1");
    EXPECT_EQ(compactDouble(-2.5), "-2.5");
    EXPECT_EQ(compactDouble(1e300), "1e+300");
    EXPECT_EQ(compactDouble(3.0), "3");
    for (double value : {0.1, 1.0 / 3.0, 6.02214076e23, 5e-324, std::numbers::pi, -1.7e308}) {
        const std::string text = compactDouble(value);
        double back = 0.0;
        std::from_chars(text.data(), text.data() + text.size(), back);
        EXPECT_EQ(back, value) << text;
    }
}

TEST(JsonWriter, WritesFloatsAsTheirOwnShortestRoundTrip) {
    std::ostringstream out;
    JsonWriter(out, 0).beginArray().value(0.1f).value(1e-3f).value(16777217.0f).endArray();
    EXPECT_EQ(out.str(), "[0.1,0.001,16777216]");
}

TEST(JsonWriter, WritesNonFiniteNumbersAsNull) {
    EXPECT_EQ(compactDouble(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(compactDouble(std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(compactDouble(-std::numeric_limits<double>::infinity()), "null");
    std::ostringstream out;
    JsonWriter(out, 0).value(std::numeric_limits<float>::quiet_NaN());
    EXPECT_EQ(out.str(), "null");
}

TEST(JsonWriter, StringLiteralIsAStringNotABool) {
    std::ostringstream out;
    JsonWriter(out, 0).value("text");
    EXPECT_EQ(out.str(), "\"text\"");
}

TEST(JsonWriter, RejectsMisuse) {
    std::ostringstream out;
    EXPECT_THROW(JsonWriter(out).key("outside"), InternalError);
    EXPECT_THROW(JsonWriter(out).beginObject().value(1), InternalError);
    EXPECT_THROW(JsonWriter(out).beginObject().endArray(), InternalError);
    EXPECT_THROW(JsonWriter(out).beginArray().endObject(), InternalError);
    EXPECT_THROW(JsonWriter(out).beginObject().key("a").endObject(), InternalError);
    EXPECT_THROW(JsonWriter(out).beginObject().key("a").key("b"), InternalError);
    EXPECT_THROW(JsonWriter(out).value(1).value(2), InternalError);
    EXPECT_THROW(JsonWriter(out).endArray(), InternalError);
}

TEST(JsonWriter, CompleteOnlyAfterTheTopLevelValueCloses) {
    std::ostringstream out;
    JsonWriter json(out);
    EXPECT_FALSE(json.complete());
    json.beginObject().key("a").beginArray();
    EXPECT_FALSE(json.complete());
    json.endArray().endObject();
    EXPECT_TRUE(json.complete());
}

} // namespace
} // namespace vkpt::json_writer_test

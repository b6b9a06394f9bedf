// json_writer.cpp — the streaming JSON writer behind --stats-json.
#include "common/json_writer.h"

#include <array>
#include <charconv>
#include <cmath>
#include <system_error>

#include "common/errors.h"

namespace vkpt {

namespace {

// JSON (RFC 8259, section 7) requires escaping the quote, the backslash and U+0000..U+001F.
void appendEscaped(std::string& result, char c) {
    switch (c) {
    case '"':
        result += "\\\"";
        return;
    case '\\':
        result += "\\\\";
        return;
    case '\b':
        result += "\\b";
        return;
    case '\f':
        result += "\\f";
        return;
    case '\n':
        result += "\\n";
        return;
    case '\r':
        result += "\\r";
        return;
    case '\t':
        result += "\\t";
        return;
    default:
        break;
    }
    if (static_cast<unsigned char>(c) < 0x20) {
        constexpr std::string_view kHex = "0123456789abcdef";
        result += "\\u00";
        result += kHex[static_cast<unsigned char>(c) >> 4];
        result += kHex[static_cast<unsigned char>(c) & 0xF];
        return;
    }
    result += c;
}

template <typename T> std::string numberText(T number) {
    std::array<char, 32> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), number);
    VKPT_ASSERT(error == std::errc(), "to_chars buffer too small");
    return std::string(buffer.data(), end);
}

} // namespace

std::string jsonQuoted(std::string_view text) {
    std::string result;
    result.reserve(text.size() + 2);
    result += '"';
    for (char c : text)
        appendEscaped(result, c);
    result += '"';
    return result;
}

JsonWriter::JsonWriter(std::ostream& out, int indent) : out_(out), indent_(indent) {}

JsonWriter& JsonWriter::beginObject() {
    return open(true, '{');
}
JsonWriter& JsonWriter::endObject() {
    return close(true, '}');
}
JsonWriter& JsonWriter::beginArray() {
    return open(false, '[');
}
JsonWriter& JsonWriter::endArray() {
    return close(false, ']');
}

JsonWriter& JsonWriter::key(std::string_view name) {
    VKPT_ASSERT(!levels_.empty() && levels_.back().isObject, "JSON key outside an object");
    Level& level = levels_.back();
    VKPT_ASSERT(!level.keyPending, "JSON key follows a key without a value");
    if (!level.empty) out_ << ',';
    newlineAndIndent();
    out_ << jsonQuoted(name) << (indent_ > 0 ? ": " : ":");
    level.empty = false;
    level.keyPending = true;
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
    return writeScalar(jsonQuoted(text));
}
JsonWriter& JsonWriter::value(bool flag) {
    return writeScalar(flag ? "true" : "false");
}
JsonWriter& JsonWriter::null() {
    return writeScalar("null");
}

JsonWriter& JsonWriter::value(double number) {
    if (!std::isfinite(number)) return null();
    return writeScalar(numberText(number));
}

JsonWriter& JsonWriter::value(float number) {
    if (!std::isfinite(number)) return null();
    return writeScalar(numberText(number));
}

JsonWriter& JsonWriter::writeSigned(std::int64_t number) {
    return writeScalar(numberText(number));
}

JsonWriter& JsonWriter::writeUnsigned(std::uint64_t number) {
    return writeScalar(numberText(number));
}

JsonWriter& JsonWriter::writeScalar(std::string_view text) {
    beforeValue();
    out_ << text;
    if (levels_.empty()) topLevelDone_ = true;
    return *this;
}

// Places a value: after its key in an object, after a comma and newline in an array.
void JsonWriter::beforeValue() {
    VKPT_ASSERT(!topLevelDone_ || !levels_.empty(), "second top-level JSON value");
    if (levels_.empty()) return;
    Level& level = levels_.back();
    if (level.isObject) {
        VKPT_ASSERT(level.keyPending, "JSON value in an object without a key");
        level.keyPending = false;
        return;
    }
    if (!level.empty) out_ << ',';
    newlineAndIndent();
    level.empty = false;
}

JsonWriter& JsonWriter::open(bool isObject, char bracket) {
    beforeValue();
    out_ << bracket;
    levels_.push_back(Level{isObject, true, false});
    return *this;
}

JsonWriter& JsonWriter::close(bool isObject, char bracket) {
    VKPT_ASSERT(!levels_.empty() && levels_.back().isObject == isObject,
                std::string("unbalanced JSON '") + bracket + "'");
    VKPT_ASSERT(!levels_.back().keyPending, "JSON object closed after a key without a value");
    const bool wasEmpty = levels_.back().empty;
    levels_.pop_back();
    if (!wasEmpty) newlineAndIndent(); // "{}" and "[]" stay on one line
    out_ << bracket;
    if (levels_.empty()) topLevelDone_ = true;
    return *this;
}

void JsonWriter::newlineAndIndent() {
    if (indent_ <= 0) return;
    out_ << '\n' << std::string(levels_.size() * std::size_t(indent_), ' ');
}

} // namespace vkpt

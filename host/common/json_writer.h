// json_writer.h — a small streaming JSON writer for machine-readable run statistics
// (--stats-json): values go straight to the stream, so nothing is held but the nesting.
#pragma once

#include <concepts>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vkpt {

// Writes one JSON value (usually an object) to a stream. Misuse — a value where a key is
// required, a key outside an object, an unbalanced end — is a programmer error and throws
// InternalError via VKPT_ASSERT, so malformed JSON is never written silently.
//
//     JsonWriter json(out);
//     json.beginObject().field("spp", 512).key("size").beginArray().value(64).value(64)
//         .endArray().endObject();
class JsonWriter {
public:
    // indent = 0 writes everything on one line; otherwise each member on its own line.
    explicit JsonWriter(std::ostream& out, int indent = 2);

    JsonWriter& beginObject();
    JsonWriter& endObject();
    JsonWriter& beginArray();
    JsonWriter& endArray();
    JsonWriter& key(std::string_view name);

    JsonWriter& value(std::string_view text);
    // Without this overload a string literal would convert to bool, a standard conversion
    // that beats the user-defined one to string_view.
    JsonWriter& value(const char* text) { return value(std::string_view(text)); }
    JsonWriter& value(bool flag);
    // Shortest text that reads back to the same double (std::to_chars); NaN and ±Inf, which
    // JSON cannot express, are written as null.
    JsonWriter& value(double number);
    // Shortest text that reads back to the same float: 0.1f is "0.1", not 0.100000001490116.
    JsonWriter& value(float number);
    template <std::integral T> JsonWriter& value(T number) {
        if constexpr (std::is_signed_v<T>)
            return writeSigned(std::int64_t(number));
        else
            return writeUnsigned(std::uint64_t(number));
    }
    JsonWriter& null();

    // key(name).value(v) in one call.
    template <typename T> JsonWriter& field(std::string_view name, const T& v) {
        return key(name).value(v);
    }

    // True once one complete top-level value has been written.
    bool complete() const { return topLevelDone_ && levels_.empty(); }

private:
    struct Level {
        bool isObject = false;
        bool empty = true;
        bool keyPending = false; // an object's key is written, its value not yet
    };

    JsonWriter& writeSigned(std::int64_t number);
    JsonWriter& writeUnsigned(std::uint64_t number);
    JsonWriter& writeScalar(std::string_view text);
    void beforeValue();
    JsonWriter& open(bool isObject, char bracket);
    JsonWriter& close(bool isObject, char bracket);
    void newlineAndIndent();

    std::ostream& out_;
    int indent_;
    std::vector<Level> levels_;
    bool topLevelDone_ = false;
};

// The JSON string literal for text, quotes included: ", \ and control characters escaped.
// Bytes >= 0x80 pass through unchanged, so UTF-8 input stays UTF-8.
std::string jsonQuoted(std::string_view text);

} // namespace vkpt

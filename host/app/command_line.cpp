// command_line.cpp — option lookup, arity checks and strict number parsing.
#include "app/command_line.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "common/errors.h"

namespace vkpt {

namespace {

std::size_t arity(const OptionSpec& spec) {
    if (spec.valueNames.empty()) return 0;
    std::istringstream words(spec.valueNames);
    std::size_t count = 0;
    for (std::string word; words >> word;)
        ++count;
    return count;
}

} // namespace

const OptionSpec* CommandLine::find(const std::string& argument) const {
    for (const OptionSpec& spec : options_) {
        if (argument == "--" + spec.longName) return &spec;
        for (char shortName : spec.shortNames)
            if (argument.size() == 2 && argument[0] == '-' && argument[1] == shortName)
                return &spec;
    }
    return nullptr;
}

std::vector<std::string> CommandLine::parse(std::span<const std::string> arguments) const {
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument.size() < 2 || argument[0] != '-') {
            positional.push_back(argument);
            continue;
        }
        const OptionSpec* spec = find(argument);
        if (!spec) throw InputError("unknown option '" + argument + "' (see --help)");
        std::size_t count = arity(*spec);
        if (count > 0 && i + count >= arguments.size())
            throw InputError("option " + argument + " needs " + spec->valueNames);
        spec->apply(arguments.subspan(i + 1, count));
        i += count;
    }
    return positional;
}

std::string CommandLine::usage(const std::string& positional) const {
    std::ostringstream out;
    out << "usage: " << program_ << " [options] " << positional << "\n\noptions:\n";
    for (const OptionSpec& spec : options_) {
        std::string names = "  --" + spec.longName;
        for (char shortName : spec.shortNames)
            names += std::string(", -") + shortName;
        if (!spec.valueNames.empty()) names += " " + spec.valueNames;
        out << names;
        out << std::string(names.size() < 32 ? 32 - names.size() : 1, ' ') << spec.help << "\n";
    }
    return out.str();
}

std::uint32_t parseUnsigned(const std::string& option, const std::string& text,
                            std::uint32_t minimum) {
    std::uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw InputError("option --" + option + ": '" + text + "' is not a whole number");
    if (value < minimum)
        throw InputError("option --" + option + ": " + text + " is below the minimum " +
                         std::to_string(minimum));
    return value;
}

float parseFloat(const std::string& option, const std::string& text) {
    float value = 0.0f;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw InputError("option --" + option + ": '" + text + "' is not a finite number");
    return value;
}

} // namespace vkpt

// command_line.h — a small table-driven parser for long and short options with fixed arity,
// so that vkpt and vkpt-ref share their options and their help text.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vkpt {

struct OptionSpec {
    std::string longName; // without the leading "--"
    std::vector<char> shortNames;
    std::string valueNames; // e.g. "W H"; empty for a flag
    std::string help;
    std::function<void(std::span<const std::string> values)> apply;
};

class CommandLine {
public:
    explicit CommandLine(std::string program) : program_(std::move(program)) {}

    void add(OptionSpec spec) { options_.push_back(std::move(spec)); }

    // Applies every option and returns the positional arguments; throws InputError naming
    // the offending option.
    std::vector<std::string> parse(std::span<const std::string> arguments) const;

    std::string usage(const std::string& positional) const;

private:
    const OptionSpec* find(const std::string& argument) const;

    std::string program_;
    std::vector<OptionSpec> options_;
};

// Strict conversions for option values: the whole text must be a number in range.
std::uint32_t parseUnsigned(const std::string& option, const std::string& text,
                            std::uint32_t minimum = 0);
float parseFloat(const std::string& option, const std::string& text);

} // namespace vkpt

#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cli {

// Command-line words split into positional arguments and --options.
// Options take a value ("--to gg", "--to=gg", "-o out.xml") unless they are
// declared as flags.
class Arguments {
public:
    Arguments(const std::vector<std::string>& words, const std::vector<std::string>& flags);

    const std::vector<std::string>& positional() const { return m_positional; }
    bool has(const std::string& option) const;
    std::optional<std::string> value(const std::string& option) const; // the last one given
    std::vector<std::string> values(const std::string& option) const; // every one given, in order
    // The first problem met while splitting ("--to needs a value"), empty if none.
    const std::string& error() const { return m_error; }
    // Options given that are not in the allowed list, as a message; empty if none.
    std::string unknownOptions(const std::vector<std::string>& allowed) const;

private:
    std::vector<std::string> m_positional;
    std::map<std::string, std::string> m_options;
    std::vector<std::pair<std::string, std::string>> m_given; // every option, in order
    std::string m_error;
};

} // namespace cli

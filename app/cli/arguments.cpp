#include "arguments.h"

#include <algorithm>

namespace cli {

namespace {

bool isOption(const std::string& word)
{
    return word.size() > 1 && word[0] == '-' && word != "-";
}

std::string canonicalName(const std::string& word)
{
    return word == "-o" ? "--output" : word;
}

} // namespace

Arguments::Arguments(const std::vector<std::string>& words, const std::vector<std::string>& flags)
{
    bool onlyPositional = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (onlyPositional || !isOption(word)) {
            m_positional.push_back(word);
            continue;
        }
        if (word == "--") {
            onlyPositional = true;
            continue;
        }
        std::string name = word;
        std::optional<std::string> inlineValue;
        if (auto equals = word.find('='); equals != std::string::npos) {
            name = word.substr(0, equals);
            inlineValue = word.substr(equals + 1);
        }
        name = canonicalName(name);
        const bool isFlag = std::find(flags.begin(), flags.end(), name) != flags.end();
        if (isFlag) {
            m_options[name] = "";
        } else if (inlineValue) {
            m_options[name] = *inlineValue;
        } else if (i + 1 < words.size()) {
            m_options[name] = words[++i];
        } else {
            if (m_error.empty())
                m_error = name + " needs a value";
            continue;
        }
        m_given.emplace_back(name, m_options[name]);
    }
}

bool Arguments::has(const std::string& option) const
{
    return m_options.count(option) != 0;
}

std::optional<std::string> Arguments::value(const std::string& option) const
{
    auto found = m_options.find(option);
    if (found == m_options.end())
        return std::nullopt;
    return found->second;
}

std::vector<std::string> Arguments::values(const std::string& option) const
{
    std::vector<std::string> out;
    for (const auto& [name, value] : m_given) {
        if (name == option)
            out.push_back(value);
    }
    return out;
}

std::string Arguments::unknownOptions(const std::vector<std::string>& allowed) const
{
    std::string unknown;
    for (const auto& [name, value] : m_options) {
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            unknown += (unknown.empty() ? "" : ", ") + name;
    }
    return unknown.empty() ? unknown : "unknown option " + unknown;
}

} // namespace cli

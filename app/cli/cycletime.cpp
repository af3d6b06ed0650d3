#include "cycletime.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace cli {

namespace {

// Milliseconds per unit, longest unit names first so "ms" wins over "m".
std::optional<double> unitMilliseconds(std::string_view text, std::size_t& length)
{
    static const std::pair<std::string_view, double> units[] = {
        {"ms", 1.0}, {"s", 1000.0}, {"m", 60'000.0}, {"h", 3'600'000.0}};
    for (const auto& [name, factor] : units) {
        if (text.size() >= name.size()) {
            std::string lower(text.substr(0, name.size()));
            for (char& c : lower)
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (lower == name) {
                length = name.size();
                return factor;
            }
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<int> parseCycleTime(std::string_view text)
{
    if (text.size() > 2 && (text[0] == 'T' || text[0] == 't') && text[1] == '#')
        text.remove_prefix(2);
    if (text.empty())
        return std::nullopt;
    double total = 0.0;
    bool sawUnit = false;
    while (!text.empty()) {
        double amount = 0.0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), amount);
        if (error != std::errc() || amount < 0.0)
            return std::nullopt;
        text.remove_prefix(static_cast<std::size_t>(end - text.data()));
        if (text.empty()) {
            if (sawUnit)
                return std::nullopt; // "1s500" is ambiguous
            total += amount;
            break;
        }
        std::size_t unitLength = 0;
        const std::optional<double> factor = unitMilliseconds(text, unitLength);
        if (!factor)
            return std::nullopt;
        total += amount * *factor;
        sawUnit = true;
        text.remove_prefix(unitLength);
    }
    const double rounded = std::round(total);
    if (std::abs(total - rounded) > 1e-9 || rounded > 2'000'000'000.0)
        return std::nullopt;
    return static_cast<int>(rounded);
}

} // namespace cli

#include "hostilemodels.h"

#include <random>
#include <string>
#include <vector>

namespace samples {

namespace {

// Code fragments that end a declaration, a block or a comment, names the
// generator uses, keywords, and characters a terminal or an editor reacts to.
const std::vector<std::string>& fragments()
{
    static const std::vector<std::string> pieces = {
        ";", "(*", "*)", "(*)", " ", "END_VAR", "VAR", ":=", "'", "\"", "\n", "\r\n", "\t", "//",
        "X : BOOL; END_VAR Injected := 13; VAR Y", "Z := TRUE; (*", "TRUE; END_VAR Injected := 1;",
        "*) Injected := 2; (*", "END_VAR Injected", "Injected.Complete", "F1.Complete", "GVL.Injected",
        "IF", "THEN", "END_IF", "State", "Entry", "GEMMA", "F1", "A1_FB", "Complete", "Initialization",
        "Stop_F1_1_MEM", "GemmaInstance", "a__b", "trailing_", "Arrêt", "\xe2\x80\xae", "\xe2\x81\xa6",
        "\x1b]0;x\x07", "\x1b[2J", "\x7f", "\xc2\x9b", "\xe2\x80\xa8", "\xff", "]]>", "<tag>", "&amp;",
        "*/", "/*", "\\", "1", "16#FF", "-", "0", "Start",
    };
    return pieces;
}

const std::vector<std::string>& ordinaryNames()
{
    static const std::vector<std::string> names = {"Start", "Stop", "Fault", "Ready", "Speed", "Level", "Count"};
    return names;
}

class HostileBuilder {
public:
    explicit HostileBuilder(std::uint32_t seed)
        : m_random(seed)
    {
    }

    core::Model build()
    {
        core::Model model;
        model.setName(text(1, 3));
        addVariables(model);
        shapeSteps(model);
        writeConditions(model);
        return model;
    }

private:
    std::size_t below(std::size_t bound) { return std::uniform_int_distribution<std::size_t>(0, bound - 1)(m_random); }
    bool chance(int percent) { return static_cast<int>(below(100)) < percent; }

    std::string text(std::size_t least, std::size_t most)
    {
        std::string out;
        const std::size_t count = least + below(most - least + 1);
        for (std::size_t i = 0; i < count; ++i)
            out += fragments()[below(fragments().size())];
        return out;
    }

    std::string defaultValue(core::IecType type)
    {
        if (chance(40))
            return text(1, 2);
        if (chance(30))
            return {};
        return type == core::IecType::Bool ? "TRUE" : core::isRealType(type) ? "1.5" : "7";
    }

    void addVariables(core::Model& model)
    {
        const std::vector<core::IecType>& types = core::allIecTypes();
        const std::size_t count = 4 + below(8);
        for (std::size_t i = 0; i < count; ++i) {
            core::Variable variable;
            variable.name = chance(30) ? ordinaryNames()[below(ordinaryNames().size())] : text(1, 3);
            variable.type = chance(60) ? core::IecType::Bool : types[below(types.size())];
            variable.defaultValue = defaultValue(variable.type);
            variable.comment = chance(70) ? text(1, 4) : std::string();
            if (model.addVariable(variable)) // a name already taken is simply dropped
                m_names.push_back(variable.name);
        }
    }

    void shapeSteps(core::Model& model)
    {
        static const core::StepType kTypes[] = {core::StepType::Simple, core::StepType::Macro,
                                                core::StepType::Enclosing};
        for (const core::Step& step : model.steps()) {
            model.setStepType(step.id, kTypes[below(3)]); // a type the step cannot have is refused: fine
            if (chance(50))
                model.setStepComment(step.id, text(1, 4));
        }
    }

    std::string variableName() { return m_names.empty() ? std::string("TRUE") : m_names[below(m_names.size())]; }

    std::string condition()
    {
        switch (below(6)) {
        case 0: return variableName();
        case 1: return variableName() + " AND NOT " + variableName();
        case 2: return variableName() + " > 3 OR " + variableName();
        case 3: return text(1, 3);
        case 4: return "TRUE";
        default: return variableName() + " OR " + variableName() + " = 2";
        }
    }

    void writeConditions(core::Model& model)
    {
        std::vector<std::string> ids;
        for (const core::Transition& transition : model.transitions())
            ids.push_back(transition.id);
        for (const std::string& id : ids) {
            model.setCondition(id, condition());
            if (chance(30))
                model.setTokens(id, {variableName(), variableName()});
            if (chance(15))
                model.setNegated(id, true);
        }
    }

    std::mt19937 m_random;
    std::vector<std::string> m_names;
};

} // namespace

core::Model hostileModel(std::uint32_t seed)
{
    return HostileBuilder(seed).build();
}

} // namespace samples

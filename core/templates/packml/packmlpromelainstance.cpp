// The calls of the instances' GRAFCETs in the PackML Promela model, as
// spec grafcet-layer.md §4.2 words one call of S_FB and the simulator's
// NestedEngine runs it: the Initialization call, the TONs, the evolutions
// (simultaneous firing, deactivation actions before activation ones, in
// step-number order), then the continuous outputs and Complete.

#include "core/condition/conditionevaluator.h"
#include "core/model/iectypes.h"
#include "core/templates/packml/packmlpromelawriter.h"

#include <algorithm>

namespace core::packml::promela {

namespace {

bool fitsPromelaInt(IecType type)
{
    return type == IecType::Bool || type == IecType::Sint || type == IecType::Int || type == IecType::Usint
           || type == IecType::Uint || type == IecType::Dint;
}

// Every step a transition names exists: otherwise it never fires.
bool firable(const NestedGrafcet& grafcet, const NestedTransition& transition)
{
    const auto exists = [&](int step) { return grafcet.step(step) != nullptr; };
    return transition.usable && std::all_of(transition.upstream.begin(), transition.upstream.end(), exists)
           && std::all_of(transition.downstream.begin(), transition.downstream.end(), exists);
}

std::string anyOf(const std::vector<std::string>& terms)
{
    std::string text;
    for (const std::string& term : terms)
        text += (text.empty() ? "" : " || ") + term;
    return text.empty() ? "0" : "(" + text + ")";
}

} // namespace

const NestedGrafcet* Writer::grafcetOf(int instance) const
{
    const ProgramInstance& i = m_program.instances[static_cast<std::size_t>(instance)];
    return i.isSkeleton() ? nullptr : &m_program.grafcets[static_cast<std::size_t>(i.grafcet)].grafcet;
}

void Writer::declareInstance(int k)
{
    const NestedGrafcet* grafcet = grafcetOf(k);
    if (!grafcet)
        return;
    std::string text = "/* " + comment(m_program.instances[static_cast<std::size_t>(k)].name) + " */ bool "
                       + Names::complete(k);
    for (const NestedStep& step : grafcet->steps)
        text += ", " + Names::step(k, step.number);
    std::size_t outputs = 0;
    for (const ContinuousOutput& output : grafcet->outputs)
        if (!output.isComplete)
            text += ", " + Names::output(k, outputs++);
    text += ";";
    if (!grafcet->timers.empty()) {
        text += " int";
        for (std::size_t t = 0; t < grafcet->timers.size(); ++t)
            text += std::string(t == 0 ? " " : ", ") + Names::timer(k, t);
        text += ";";
    }
    m_declarations.line(text);
}

void Writer::writeInitializationCall(int k)
{
    const NestedGrafcet& grafcet = *grafcetOf(k);
    std::string text = Names::complete(k) + " = 0;";
    for (const NestedStep& step : grafcet.steps)
        text += " " + Names::step(k, step.number) + " = " + (step.initial ? "1" : "0") + ";";
    for (std::size_t t = 0; t < grafcet.timers.size(); ++t)
        text += " " + Names::timer(k, t) + " = 0;";
    m_process.line("/* the Initialization call */");
    m_process.line(text);
    for (const NestedStep& step : grafcet.steps)
        if (step.initial)
            writeStored(k, step.onActivation);
    writeOutputs(k);
}

void Writer::writeOrdinaryCall(int k)
{
    const NestedGrafcet& grafcet = *grafcetOf(k);
    Lines& p = m_process;
    p.line("/* the call of " + comment(m_program.instances[static_cast<std::size_t>(k)].name) + " */");
    for (std::size_t t = 0; t < grafcet.timers.size(); ++t) {
        const std::string timer = Names::timer(k, t);
        const std::string runs = std::to_string(m_names.runsToElapse(grafcet, t));
        p.line("if :: " + Names::step(k, grafcet.timers[t].step) + " -> " + timer + " = (" + timer + " < " + runs + " -> "
               + timer + " + 1 : " + timer + "); :: else -> " + timer + " = 0; fi;");
    }
    writeEvolution(k, true);
    if (grafcet.rule == EvolutionRule::UntilStable)
        for (int e = 1; e < grafcet.maxEvolutions; ++e) {
            p.line("if");
            p.line(":: any ->");
            p.in();
            writeEvolution(k, false);
            p.out();
            p.line(":: else -> skip;");
            p.line("fi;");
        }
    writeOutputs(k);
    writeStepMarkers(k);
}

// IEC 60848 rules 2-5: every enabled transition whose receptivity holds
// fires at once; `any` says whether one did.
void Writer::writeEvolution(int k, bool first)
{
    const NestedGrafcet& grafcet = *grafcetOf(k);
    Lines& p = m_process;
    for (std::size_t t = 0; t < grafcet.transitions.size(); ++t) {
        const NestedTransition& transition = grafcet.transitions[t];
        std::string value = "0";
        if (firable(grafcet, transition)) {
            value.clear();
            for (int step : transition.upstream)
                value += Names::step(k, step) + " && ";
            const Place place{k, &grafcet, first, &transition.timerOfNode};
            value += "(" + m_names.expression(transition.receptivity.expression, place) + ")";
        }
        p.line("f" + std::to_string(t) + " = " + value + "; /* T" + std::to_string(transition.number) + " */");
    }
    std::vector<std::string> fired;
    for (std::size_t t = 0; t < grafcet.transitions.size(); ++t)
        fired.push_back("f" + std::to_string(t));
    p.line("any = " + anyOf(fired) + ";");
    p.line("if");
    p.line(":: any ->");
    p.in();
    for (std::size_t s = 0; s < grafcet.steps.size(); ++s) {
        const int number = grafcet.steps[s].number;
        std::vector<std::string> leaving, entering;
        for (std::size_t t = 0; t < grafcet.transitions.size(); ++t) {
            const NestedTransition& transition = grafcet.transitions[t];
            if (std::count(transition.upstream.begin(), transition.upstream.end(), number))
                leaving.push_back("f" + std::to_string(t));
            if (std::count(transition.downstream.begin(), transition.downstream.end(), number))
                entering.push_back("f" + std::to_string(t));
        }
        const std::string x = Names::step(k, number);
        const std::string index = std::to_string(s);
        p.line("lv" + index + " = " + anyOf(leaving) + " && !" + anyOf(entering) + "; en" + index + " = " + anyOf(entering)
               + " && !" + x + ";");
    }
    for (std::size_t s = 0; s < grafcet.steps.size(); ++s) {
        const std::string x = Names::step(k, grafcet.steps[s].number);
        const std::string index = std::to_string(s);
        p.line(x + " = (lv" + index + " -> 0 : (en" + index + " -> 1 : " + x + "));");
    }
    for (std::size_t s = 0; s < grafcet.steps.size(); ++s)
        if (!grafcet.steps[s].onDeactivation.empty()) {
            p.line("if :: lv" + std::to_string(s) + " ->");
            p.in();
            writeStored(k, grafcet.steps[s].onDeactivation);
            p.out();
            p.line(":: else -> skip; fi;");
        }
    for (std::size_t s = 0; s < grafcet.steps.size(); ++s) {
        const NestedStep& step = grafcet.steps[s];
        std::string timers;
        for (int timer : step.timers)
            timers += Names::timer(k, static_cast<std::size_t>(timer)) + " = 0; ";
        if (step.onActivation.empty() && timers.empty())
            continue;
        p.line("if :: en" + std::to_string(s) + " ->");
        p.in();
        writeStored(k, step.onActivation);
        if (!timers.empty())
            p.line(timers);
        p.out();
        p.line(":: else -> skip; fi;");
    }
    p.out();
    p.line(":: else -> skip;");
    p.line("fi;");
}

// Stored actions in list order; an integer is stored wrapped into its type.
void Writer::writeStored(int k, const std::vector<NestedAction>& actions)
{
    const NestedGrafcet& grafcet = *grafcetOf(k);
    for (const NestedAction& action : actions) {
        if (!action.usable)
            continue;
        const cond::ActionSyntax& syntax = action.parsed.action;
        const std::string value = syntax.form == cond::ActionForm::Set ? "1"
                                  : syntax.form == cond::ActionForm::Reset
                                      ? "0"
                                      : m_names.expression(syntax.value, Place{k, &grafcet, false, nullptr});
        if (action.targetIsComplete) {
            m_process.line(Names::complete(k) + " = (" + value + " != 0); /* " + comment(action.text) + " */");
            continue;
        }
        const int slot = m_program.slotOf(action.target);
        if (slot < 0)
            continue;
        const Variable& variable = m_program.variables[static_cast<std::size_t>(slot)];
        if (variable.kind == VariableKind::Input || !fitsPromelaInt(variable.type))
            throw Unsupported("a stored action writes " + variable.name + ", an input or a type the export does not hold");
        const std::string target = Names::stored(slot);
        if (variable.type == IecType::Bool || variable.type == IecType::Dint) {
            m_process.line(target + " = " + value + "; /* " + comment(action.text) + " */");
            continue;
        }
        const cond::IntegerRange range = cond::integerRange(variable.type);
        const std::string low = std::to_string(range.low);
        const std::string width = std::to_string(range.high - range.low + 1);
        m_process.line(target + " = " + value + "; /* " + comment(action.text) + " */");
        m_process.line(target + " = " + low + " + ((" + target + " - " + low + ") % " + width + " + " + width + ") % "
                       + width + ";");
    }
}

// The continuous outputs and Complete from the situation the call ends with.
void Writer::writeOutputs(int k)
{
    const NestedGrafcet& grafcet = *grafcetOf(k);
    std::vector<std::string> assignments;
    std::size_t index = 0;
    for (const ContinuousOutput& output : grafcet.outputs) {
        std::vector<std::string> drivers;
        for (const ContinuousOutput::Driver& driver : output.drivers) {
            const NestedStep& step = *grafcet.step(driver.step);
            const cond::Expression& condition = step.continuous[static_cast<std::size_t>(driver.action)].parsed.action.condition;
            drivers.push_back("(" + Names::step(k, driver.step) + " && ("
                              + m_names.expression(condition, Place{k, &grafcet, false, nullptr}) + "))");
        }
        const std::string scratch = output.isComplete ? "nc" : "no" + std::to_string(index);
        m_process.line(scratch + " = " + anyOf(drivers) + ";");
        assignments.push_back(output.isComplete ? Names::complete(k) + " = nc;"
                                                : Names::output(k, index++) + " = " + scratch + ";");
    }
    for (const std::string& assignment : assignments)
        m_process.line(assignment);
}

void Writer::writeStepMarkers(int k)
{
    const ProgramInstance& instance = m_program.instances[static_cast<std::size_t>(k)];
    for (const NestedStep& step : grafcetOf(k)->steps) {
        PackmlMarker m;
        m.kind = PackmlMarkerKind::StepActive;
        m.mode = instance.mode;
        m.state = instance.state;
        m.instance = k;
        m.step = step.number;
        markIf(Names::step(k, step.number), m, instance.name + ".X" + std::to_string(step.number) + " active");
    }
}

// Time goes on for the instances not called in this scan: their running TONs age one scan.
void Writer::writeTimersAging()
{
    for (std::size_t k = 0; k < m_program.instances.size(); ++k) {
        const NestedGrafcet* grafcet = grafcetOf(static_cast<int>(k));
        if (!grafcet)
            continue;
        for (std::size_t t = 0; t < grafcet->timers.size(); ++t) {
            const std::string timer = Names::timer(static_cast<int>(k), t);
            m_process.line("if :: ci != " + std::to_string(k) + " && " + timer + " > 0 && " + timer + " < "
                           + std::to_string(m_names.runsToElapse(*grafcet, t)) + " -> " + timer + " = " + timer
                           + " + 1; :: else -> skip; fi;");
        }
    }
}

} // namespace core::packml::promela

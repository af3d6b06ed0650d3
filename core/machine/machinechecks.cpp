#include "core/machine/machinechecks.h"

#include "core/condition/actionparser.h"
#include "core/model/iectypes.h"
#include "core/model/model.h"

#include <map>
#include <set>
#include <string>

namespace core::machine {

namespace {

// Outputs some action of an effective GRAFCET can make TRUE or give a
// value (a reset alone drives nothing), by upper-case name.
std::set<std::string> drivenOutputs(const Model& model)
{
    std::set<std::string> driven;
    for (const Step& step : model.steps()) {
        const Grafcet* grafcet = model.effectiveGrafcet(step.id);
        if (!grafcet)
            continue;
        for (const GrafcetStep& nested : grafcet->steps()) {
            for (const GrafcetAction& action : nested.actions) {
                const cond::ActionParseResult parsed = cond::parseAction(action.text);
                if (parsed.ok() && parsed.action.form != cond::ActionForm::Reset)
                    driven.insert(toUpperAscii(parsed.action.target));
            }
        }
    }
    return driven;
}

std::string_view directionNeeds(SignalDirection direction)
{
    return direction == SignalDirection::Actuator ? "output" : "input";
}

class MachineChecker {
public:
    explicit MachineChecker(const Model& model) : m_model(model), m_driven(drivenOutputs(model)) {}

    std::vector<Diagnostic> run()
    {
        for (const Component& component : m_model.machine().components) {
            checkSignals(component);
            checkParameters(component);
            checkConveyor(component);
        }
        return std::move(m_diagnostics);
    }

private:
    struct Writer {
        std::string component;
        std::string role;
    };

    void add(const Component& component, std::string code, Severity severity, std::string_view field,
             std::string message, std::vector<std::string> arguments)
    {
        Diagnostic d;
        d.code = std::move(code);
        d.severity = severity;
        d.target = Diagnostic::Target::MachineComponent;
        d.element = component.name;
        d.field = std::string(field);
        d.message = std::move(message);
        d.arguments = std::move(arguments);
        m_diagnostics.push_back(std::move(d));
    }

    void checkSignals(const Component& component)
    {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        for (std::size_t i = 0; i < spec.roles.size() && i < component.wires.size(); ++i) {
            const RoleSpec& role = spec.roles[i];
            const std::string& name = component.wires[i];
            if (name.empty()) {
                if (role.required)
                    add(component, "GG607", Severity::Error, role.key,
                        component.name + " has no variable for its " + std::string(role.key) + " signal",
                        {component.name, std::string(role.key)});
                continue;
            }
            checkSignal(component, role, name);
        }
    }

    void checkSignal(const Component& component, const RoleSpec& role, const std::string& name)
    {
        const std::string key(role.key);
        const Variable* variable = m_model.variable(name);
        if (!variable) {
            add(component, "GG601", Severity::Error, key,
                component.name + "'s " + key + " signal names '" + name + "', which is no variable of the model",
                {component.name, key, name});
            return;
        }
        const VariableKind wanted = role.direction == SignalDirection::Actuator ? VariableKind::Output
                                                                                 : VariableKind::Input;
        if (variable->kind != wanted) {
            add(component, "GG602", Severity::Error, key,
                component.name + "'s " + key + " signal is " + variable->name + ", an "
                    + std::string(variableKindName(variable->kind)) + " variable; it needs an "
                    + std::string(directionNeeds(role.direction)),
                {component.name, key, variable->name, std::string(variableKindName(variable->kind)),
                 std::string(directionNeeds(role.direction))});
        }
        if (variable->type != IecType::Bool) {
            add(component, "GG603", Severity::Error, key,
                component.name + "'s " + key + " signal is " + variable->name + ", of type "
                    + std::string(iecTypeName(variable->type)) + "; a machine signal is BOOL",
                {component.name, key, variable->name, std::string(iecTypeName(variable->type))});
        }
        if (role.direction == SignalDirection::Actuator) {
            if (variable->kind == VariableKind::Output && !m_driven.count(toUpperAscii(variable->name)))
                add(component, "GG605", Severity::Warning, key,
                    component.name + "'s " + key + " signal " + variable->name
                        + " is driven by no action of the program: the component never moves",
                    {component.name, key, variable->name});
            return;
        }
        const auto [first, inserted] = m_writers.emplace(toUpperAscii(variable->name), Writer{component.name, key});
        if (!inserted)
            add(component, "GG604", Severity::Error, key,
                variable->name + " is wired to " + component.name + "'s " + key + " signal and to "
                    + first->second.component + "'s " + first->second.role
                    + " signal: an input has one source",
                {component.name, key, variable->name, first->second.component, first->second.role});
    }

    void checkParameters(const Component& component)
    {
        const ComponentKindSpec& spec = kindSpec(component.kind);
        for (std::size_t i = 0; i < spec.parameters.size() && i < component.parameters.size(); ++i) {
            const ParameterSpec& parameter = spec.parameters[i];
            const std::int64_t value = component.parameters[i];
            const std::string key(parameter.key);
            std::string problem;
            switch (parameter.kind) {
            case ParameterKind::TravelTime:
                if (value < 1 || value > kMaxMachineTimeMs)
                    problem = "a travel time is 1 to " + std::to_string(kMaxMachineTimeMs) + " ms";
                break;
            case ParameterKind::Delay:
                if (value < 0 || value > kMaxMachineTimeMs)
                    problem = "a delay is 0 to " + std::to_string(kMaxMachineTimeMs) + " ms";
                break;
            case ParameterKind::PartCount:
                if (value != kUnlimitedParts && (value < 0 || value > kMaxParts))
                    problem = "a part count is 0 to " + std::to_string(kMaxParts) + ", or unlimited";
                break;
            }
            if (!problem.empty())
                add(component, "GG606", Severity::Error, key,
                    component.name + "'s " + key + " is " + std::to_string(value) + ": " + problem,
                    {component.name, key, std::to_string(value)});
        }
    }

    void checkConveyor(const Component& component)
    {
        if (!kindSpec(component.kind).feedsConveyor)
            return;
        const Component* conveyor = m_model.machine().find(component.conveyor);
        if (conveyor && conveyor->kind == ComponentKind::Conveyor)
            return;
        add(component, "GG608", Severity::Error, "conveyor",
            component.name + " feeds '" + component.conveyor + "', which is no conveyor of the machine",
            {component.name, component.conveyor});
    }

    const Model& m_model;
    std::set<std::string> m_driven;
    std::map<std::string, Writer> m_writers; // input (upper case) -> the first role wired to it
    std::vector<Diagnostic> m_diagnostics;
};

} // namespace

std::vector<Diagnostic> checkMachine(const Model& model)
{
    return MachineChecker(model).run();
}

} // namespace core::machine

#include "editor/simulation/packml/packmlgrafcetmarks.h"

#include "editor/grafcet/grafcetscene.h"
#include "editor/simulation/packml/packmlsimulationsession.h"
#include "editor/stdstring.h"

#include "core/templates/packml/packmlconfiguration.h"

namespace editor {

namespace {

// The index of `instance` when it runs the GRAFCET of `key`, else -1.
int runningGrafcet(const core::packml::PackmlProgram& program, const core::packml::ProgramInstance* instance,
                   const std::string& key)
{
    if (!instance || instance->isSkeleton()
        || program.grafcets[static_cast<std::size_t>(instance->grafcet)].key != key)
        return -1;
    return static_cast<int>(instance - program.instances.data());
}

} // namespace

GrafcetSimulationSnapshot packmlGrafcetSnapshot(const PackmlSimulationSession& session, const std::string& key)
{
    GrafcetSimulationSnapshot shown;
    const core::packml::PackmlSimulator* simulator = session.simulator();
    const auto owner = core::packml::parseGrafcetKey(key);
    if (!simulator || !owner)
        return shown;
    const core::packml::PackmlProgram& program = simulator->program();
    const int current = runningGrafcet(program, program.instance(simulator->mode(), simulator->state()), key);
    const int index = current >= 0 ? current : runningGrafcet(program, program.instance(owner->first, owner->second), key);
    if (index < 0)
        return shown;
    shown.engine = simulator->engine(index);
    shown.owner = fromStd(program.instances[static_cast<std::size_t>(index)].name);
    if (index != current)
        return shown; // not the current state's: as it was left
    // As GEMMA's: in the scan that enters the state the function block has not run yet.
    shown.runs = !simulator->entry();
    shown.justEntered = simulator->entry();
    shown.resumes = simulator->entry() && simulator->resume();
    const core::packml::PackmlScanRecord* record = session.shownRecord();
    if (shown.runs && record && record->calledInstance == index)
        shown.fired = shown.engine->firedTransitions();
    return shown;
}

GrafcetSimulationMarks* addPackmlGrafcetMarks(PackmlSimulationSession* session, GrafcetScene* scene, QObject* parent)
{
    const std::string key = scene->stepId().toStdString();
    auto* marks = new GrafcetSimulationMarks([session, key] { return packmlGrafcetSnapshot(*session, key); }, scene, parent);
    QObject::connect(session, &PackmlSimulationSession::activeChanged, marks, &GrafcetSimulationMarks::update);
    QObject::connect(session, &PackmlSimulationSession::stepped, marks, &GrafcetSimulationMarks::update);
    QObject::connect(session, &PackmlSimulationSession::historyMoved, marks, &GrafcetSimulationMarks::update);
    return marks;
}

} // namespace editor

#include "editor/text/packmlverificationtext.h"

#include "core/templates/packml/packmlverifier.h"

#include <QCoreApplication>

namespace editor {

namespace {

// Its tr() gives lupdate the context of these texts.
class PackmlVerificationText {
    Q_DECLARE_TR_FUNCTIONS(PackmlVerificationText)

public:
    static QString text(const core::VerificationFinding& f);
    static QString executeEntryText(const core::VerificationFinding& f);
};

QString argument(const core::VerificationFinding& f, std::size_t index)
{
    return index < f.arguments.size() ? QString::fromStdString(f.arguments[index]) : QString();
}

QString PackmlVerificationText::executeEntryText(const core::VerificationFinding& f)
{
    const QString mode = argument(f, 0);
    const QString rule = argument(f, 1);
    if (rule == QLatin1String("afresh"))
        return tr("In %1, Execute, entered again from the Hold or Suspend loop, started afresh instead of resuming "
                  "where it was paused.")
            .arg(mode);
    if (rule == QLatin1String("resumed"))
        return tr("In %1, Execute resumed where it should have started afresh from its initial situation.").arg(mode);
    return tr("In %1, Execute resumed in a situation other than the one it was paused in.").arg(mode);
}

QString PackmlVerificationText::text(const core::VerificationFinding& f)
{
    namespace pv = core::packml::verification;
    const std::string& code = f.code;
    const std::size_t n = f.arguments.size();
    if (code == core::verification::kIncomplete && n == 2 && argument(f, 0) == QLatin1String("stuck"))
        return tr("Stuck states were not decided in %1: timers longer than one cycle may or may not have elapsed, "
                  "and the ways to Complete found there let timers elapse in an order the PLC's may not. Every other "
                  "finding is decided.")
            .arg(argument(f, 1));
    if (code == core::verification::kIncomplete)
        return tr("The verification was not exhaustive (its time or size limit, timers or numeric inputs it explores "
                  "only in part): stuck states, states never active and commands never accepted were not decided, "
                  "and the absence of other findings is not a proof.");
    if (code == pv::kStuckGrafcet && n >= 2)
        return tr("In %1, the GRAFCET of %2 can reach a situation from which Complete never becomes TRUE: only Stop "
                  "or Abort then leave %2.")
            .arg(argument(f, 0), argument(f, 1));
    if (code == pv::kAbortingStuck && n >= 1)
        return tr("In %1, Aborting can reach a situation from which Aborted is never reached: nothing leaves it.")
            .arg(argument(f, 0));
    if (code == pv::kDisabledStateActive && n >= 2)
        return tr("%2 was active at the end of a scan in %1, a mode that disables it.").arg(argument(f, 0),
                                                                                          argument(f, 1));
    if (code == pv::kModeChangeOutside && n >= 2)
        return tr("The mode changed from %1 in %2, a state where this change is not allowed.")
            .arg(argument(f, 0), argument(f, 1));
    if (code == pv::kNeverActive && n == 1)
        return tr("%1 is never the current mode.").arg(argument(f, 0));
    if (code == pv::kNeverActive && n >= 2)
        return tr("%2 is enabled in %1 but never active there.").arg(argument(f, 0), argument(f, 1));
    if (code == pv::kNeverAccepted && n >= 1)
        return tr("The %1 command is accepted in no reachable configuration.").arg(argument(f, 0));
    if (code == pv::kOutputOnAbort && n >= 3)
        return tr("In %1, continuous outputs are TRUE at the end of the scan that enters %2: %3.")
            .arg(argument(f, 0), argument(f, 1), argument(f, 2));
    if (code == pv::kStoredOutputOnAbort && n >= 3)
        return tr("In %1, stored outputs can still be TRUE when %2 is entered: %3.")
            .arg(argument(f, 0), argument(f, 1), argument(f, 2));
    if (code == pv::kExecuteEntry && n >= 1)
        return executeEntryText(f);
    return {};
}

} // namespace

QString packmlVerificationText(const core::VerificationFinding& finding)
{
    if (finding.origin != core::FindingOrigin::PackML)
        return {};
    return PackmlVerificationText::text(finding);
}

} // namespace editor

#include "editor/text/gemmastatenames.h"

#include <QCoreApplication>

namespace editor {

namespace {

struct StateName {
    const char* id;
    const char* name;
};

// Literal texts so that lupdate finds them; a test checks they match the
// core template.
constexpr StateName kStateNames[] = {
    {"A1", QT_TRANSLATE_NOOP("StateNames", "Stop in initial state")},
    {"A2", QT_TRANSLATE_NOOP("StateNames", "Stop requested at end of cycle")},
    {"A3", QT_TRANSLATE_NOOP("StateNames", "Stop requested in a given state")},
    {"A4", QT_TRANSLATE_NOOP("StateNames", "Stop obtained")},
    {"A5", QT_TRANSLATE_NOOP("StateNames", "Preparation for restart after failure")},
    {"A6", QT_TRANSLATE_NOOP("StateNames", "Operative part reset to initial state")},
    {"A7", QT_TRANSLATE_NOOP("StateNames", "Operative part set to a given state")},
    {"F1", QT_TRANSLATE_NOOP("StateNames", "Normal production")},
    {"F2", QT_TRANSLATE_NOOP("StateNames", "Preparation run")},
    {"F3", QT_TRANSLATE_NOOP("StateNames", "Closing run")},
    {"F4", QT_TRANSLATE_NOOP("StateNames", "Verification run out of order")},
    {"F5", QT_TRANSLATE_NOOP("StateNames", "Verification run in order")},
    {"F6", QT_TRANSLATE_NOOP("StateNames", "Test run")},
    {"D1", QT_TRANSLATE_NOOP("StateNames", "Emergency stop")},
    {"D2", QT_TRANSLATE_NOOP("StateNames", "Diagnosis and/or failure handling")},
    {"D3", QT_TRANSLATE_NOOP("StateNames", "Production despite failure")},
};

} // namespace

QString officialStateName(const QString& id)
{
    for (const StateName& entry : kStateNames) {
        if (id == QLatin1String(entry.id))
            return QCoreApplication::translate("StateNames", entry.name);
    }
    return {};
}

QString officialFamilyName(core::Family family)
{
    switch (family) {
    case core::Family::A: return QCoreApplication::translate("StateNames", "Stop procedures");
    case core::Family::F: return QCoreApplication::translate("StateNames", "Operation procedures");
    case core::Family::D: return QCoreApplication::translate("StateNames", "Failure procedures");
    }
    return {};
}

} // namespace editor

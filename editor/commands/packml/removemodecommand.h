#pragma once

#include "editor/commands/modelcommand.h"

#include "core/model/grafcet.h"
#include "core/templates/packml/packmlconfiguration.h"

#include <QCoreApplication>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace editor {

// "Remove mode 4 Cleaning": the mode, its GRAFCETs, and every "same as" it
// of the other modes (which become none); undo puts all of them back.
// Refused for Production (1), the mode every unit has (spec packml.md §3.1).
class RemoveModeCommand : public ModelCommand {
    Q_DECLARE_TR_FUNCTIONS(RemoveModeCommand)

public:
    RemoveModeCommand(Document& document, int mode);
    int id() const override;

private:
    // A choice of another mode that named the removed one.
    struct Redirected {
        int mode;
        core::packml::State state;
    };

    core::Status apply() override;
    core::Status revert() override;
    void capture();

    int m_mode;
    core::packml::Mode m_removed;
    std::map<std::string, core::Grafcet, std::less<>> m_grafcets; // by grafcetKey
    std::vector<Redirected> m_redirected;
    bool m_wasInitialMode = false;
};

} // namespace editor

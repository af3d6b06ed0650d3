#pragma once

#include "editor/export/specificationpages.h"

namespace editor {
class ChartScene;
class MachineScene;
}

namespace editor::specification {

// The GEMMA model's specification: the title page, the GEMMA chart, the
// states, transitions and variables, the machine (when the model has one),
// each nested GRAFCET, the code outline.
class GemmaSpecificationPages : public SpecificationPages {
    Q_DECLARE_TR_FUNCTIONS(SpecificationExport)

public:
    GemmaSpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device,
                            const QSizeF& printable, double dotsPerPoint);

    // "F1 Normal production".
    static QString stateLabel(const QString& id);

private:
    std::vector<Section> sections() override;

    void planTitlePage();
    void planChart();
    void planStates();
    void planTransitions();
    void planMachine();
    void planMachineDrawing();
    void planGrafcet(qsizetype index);
    void planCode();
    QString describePou(const core::PlcPou& pou, const QString& program) const;

    // The sections, as the running header names them.
    QString m_titleSection;
    QString m_chartSection;
    QString m_tablesSection;
    QString m_machineSection;
    QString m_grafcetSection;
    QString m_codeSection;
    QStringList m_grafcetSteps; // the GRAFCETs that generate code, in state order
    // The contents' entries.
    std::size_t m_chartEntry = 0;
    std::size_t m_statesEntry = 0;
    std::size_t m_transitionsEntry = 0;
    std::size_t m_variablesEntry = 0;
    std::size_t m_machineEntry = 0;
    std::size_t m_grafcetsEntry = 0; // then one per GRAFCET
    std::size_t m_codeEntry = 0;
    ChartScene* m_chartScene = nullptr;
    MachineScene* m_machineScene = nullptr; // when the model has a machine
};

} // namespace editor::specification

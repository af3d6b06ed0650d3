#pragma once

#include "editor/export/specificationpages.h"

#include "core/templates/packml/packmlconfiguration.h"

#include <utility>

namespace editor {
class PackmlChartScene;
}

namespace editor::specification {

// The PackML model's specification: the title page, the chart of each unit
// mode on its landscape page, the commands, the modes and what each runs in
// its acting states and Execute, the variables, each own GRAFCET, the code
// outline.
class PackmlSpecificationPages : public SpecificationPages {
    Q_DECLARE_TR_FUNCTIONS(SpecificationExport)

public:
    PackmlSpecificationPages(Document& document, const QDateTime& date, QPagedPaintDevice& device,
                             const QSizeF& printable, double dotsPerPoint);

    // "Production · Execute": the heading of an own GRAFCET's first page.
    static QString grafcetTitle(const core::packml::Mode& mode, core::packml::State state);

private:
    std::vector<Section> sections() override;

    void planTitlePage();
    void planCharts();
    void planCommands();
    void planModes();
    void planModeGrafcets(const core::packml::Mode& mode);
    void planGrafcet(qsizetype index);
    void planCode();
    QString describePou(const core::PlcPou& pou, const QString& program) const;
    // What runs in `state` in `mode`: own (its page), same as mode k, none.
    QString grafcetChoiceText(const core::packml::Mode& mode, core::packml::State state) const;
    QString stateListText(const core::packml::StateSet& states) const;

    const core::packml::Configuration& m_configuration;
    QString m_titleSection;
    QString m_chartSection;
    QString m_tablesSection;
    QString m_grafcetSection;
    QString m_codeSection;
    // The own GRAFCETs that run somewhere, in mode then state order.
    std::vector<std::pair<int, core::packml::State>> m_grafcets;
    std::size_t m_chartEntry = 0; // then one per mode
    std::size_t m_commandsEntry = 0;
    std::size_t m_modesEntry = 0;
    std::size_t m_variablesEntry = 0;
    std::size_t m_grafcetsEntry = 0; // then one per GRAFCET
    std::size_t m_codeEntry = 0;
    PackmlChartScene* m_chartScene = nullptr;
};

} // namespace editor::specification

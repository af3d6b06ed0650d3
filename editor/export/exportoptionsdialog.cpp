#include "editor/export/exportoptionsdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace editor {

ExportOptionsDialog::ExportOptionsDialog(Kind kind, core::Dialect dialect, bool singleFile, QWidget* parent)
    : QDialog(parent)
    , m_kind(kind)
{
    setObjectName("exportOptionsDialog");
    setWindowTitle(kind == Kind::PlcOpen ? tr("Export PLCopen XML") : tr("Export Structured Text"));

    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);

    if (kind == Kind::StructuredText) {
        m_folderButton = new QRadioButton(tr("One file per POU, in a &folder"), this);
        m_singleFileButton = new QRadioButton(tr("One &IEC 61131-3 file with every POU"), this);
        (singleFile ? m_singleFileButton : m_folderButton)->setChecked(true);
        auto* choice = new QVBoxLayout;
        choice->addWidget(m_folderButton);
        choice->addWidget(m_singleFileButton);
        form->addRow(tr("Files:"), choice);
        connect(m_singleFileButton, &QRadioButton::toggled, this, &ExportOptionsDialog::updateDialectEnabled);
    }

    m_dialectCombo = new QComboBox(this);
    m_dialectCombo->setObjectName("dialectCombo");
    for (core::Dialect d : {core::Dialect::Iec, core::Dialect::Codesys})
        m_dialectCombo->addItem(dialectText(d), static_cast<int>(d));
    m_dialectCombo->setCurrentIndex(m_dialectCombo->findData(static_cast<int>(dialect)));
    form->addRow(tr("&Dialect:"), m_dialectCombo);

    m_dialectHint = new QLabel(this);
    m_dialectHint->setWordWrap(true);
    m_dialectHint->setText(kind == Kind::PlcOpen
                               ? tr("IEC writes PLCopen TC6 XML 2.01 with the globals in the configuration. "
                                    "CODESYS writes what CODESYS V3.5 imports, with a GVL.")
                               : tr("The single file is always IEC 61131-3: CODESYS code names a GVL "
                                    "that IEC compilers do not know."));
    layout->addWidget(m_dialectHint);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export…"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    updateDialectEnabled();
    // Room for the dialect names and a two-line hint.
    setMinimumWidth(fontMetrics().averageCharWidth() * 60);
}

core::Dialect ExportOptionsDialog::dialect() const
{
    if (singleFile())
        return core::Dialect::Iec;
    return static_cast<core::Dialect>(m_dialectCombo->currentData().toInt());
}

bool ExportOptionsDialog::singleFile() const
{
    return m_singleFileButton && m_singleFileButton->isChecked();
}

QString ExportOptionsDialog::dialectText(core::Dialect dialect)
{
    switch (dialect) {
    case core::Dialect::Iec:
        return tr("IEC 61131-3 (Beremiz, OpenPLC, TwinCAT…)");
    case core::Dialect::Codesys:
        return tr("CODESYS");
    }
    return {};
}

void ExportOptionsDialog::updateDialectEnabled()
{
    m_dialectCombo->setEnabled(!singleFile());
    if (m_kind == Kind::StructuredText)
        m_dialectHint->setVisible(singleFile());
}

} // namespace editor

#include "editor/window/newmodeldialog.h"

#include "editor/app/settings.h"

#include "core/templates/packml/packmlmodel.h"

#include <QAbstractButton>
#include <QButtonGroup>
#include <QDialogButtonBox>
#include <QLabel>
#include <QRadioButton>
#include <QVBoxLayout>

namespace editor {

namespace {

struct ChoiceText {
    NewModelDialog::Choice choice;
    const char* objectName;
    QString title;
    QString description;
};

QList<ChoiceText> choiceTexts()
{
    return {
        {NewModelDialog::Choice::Gemma, "templateGemma", NewModelDialog::tr("GEMMA"),
         NewModelDialog::tr("The GEMMA chart (stop, operation and failure procedures) with a nested GRAFCET in "
                            "each macro-step: the GEMMA-GRAFCET method.")},
        {NewModelDialog::Choice::Packml2015, "templatePackml2015", NewModelDialog::tr("PackML, 2015 edition"),
         NewModelDialog::tr("The ISA-TR88.00.02-2015 state machine with unit modes: Production, Maintenance and "
                            "Manual, a GRAFCET in each acting state.")},
        {NewModelDialog::Choice::Packml2022, "templatePackml2022", NewModelDialog::tr("PackML, 2022 edition"),
         NewModelDialog::tr("The ISA-TR88.00.02-2022 state machine: as 2015, with the Complete command that ends "
                            "Execute.")},
    };
}

} // namespace

NewModelDialog::NewModelDialog(Choice initial, QWidget* parent)
    : QDialog(parent)
    , m_choices(new QButtonGroup(this))
{
    setObjectName(QStringLiteral("newModelDialog"));
    setWindowTitle(tr("New Model"));
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Which chart does the new model fill in?"), this);
    layout->addWidget(intro);
    for (const ChoiceText& text : choiceTexts()) {
        auto* button = new QRadioButton(text.title, this);
        button->setObjectName(QLatin1String(text.objectName));
        QFont bold = button->font();
        bold.setBold(true);
        button->setFont(bold);
        m_choices->addButton(button, static_cast<int>(text.choice));
        auto* description = new QLabel(text.description, this);
        description->setWordWrap(true);
        description->setIndent(24);
        description->setBuddy(button);
        layout->addWidget(button);
        layout->addWidget(description);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    setChoice(initial);
    setMinimumWidth(420);
}

NewModelDialog::Choice NewModelDialog::choice() const
{
    return static_cast<Choice>(m_choices->checkedId());
}

void NewModelDialog::setChoice(Choice choice)
{
    if (QAbstractButton* button = m_choices->button(static_cast<int>(choice))) {
        button->setChecked(true);
        button->setFocus();
    }
}

QString NewModelDialog::settingName(Choice choice)
{
    switch (choice) {
    case Choice::Packml2015: return QStringLiteral("packml-2015");
    case Choice::Packml2022: return QStringLiteral("packml-2022");
    case Choice::Gemma: break;
    }
    return QStringLiteral("gemma");
}

NewModelDialog::Choice NewModelDialog::fromSettingName(const QString& name)
{
    for (Choice choice : {Choice::Packml2015, Choice::Packml2022}) {
        if (name == settingName(choice))
            return choice;
    }
    return Choice::Gemma;
}

core::Model NewModelDialog::newModel(Choice choice, const Settings& settings)
{
    core::Model model = choice == Choice::Gemma ? core::Model()
                                                : core::packml::newModel(choice == Choice::Packml2022
                                                                             ? core::packml::Edition::Y2022
                                                                             : core::packml::Edition::Y2015);
    model.setCycleTimeMs(settings.defaultCycleTimeMs());
    model.setDialect(settings.defaultDialect());
    return model;
}

} // namespace editor

// Model Settings on a PackML model (PackmlSettingsWidget): the edition, the
// options and the initial state, applied as one undo step.

#include "packmldocktestsupport.h"

#include "editor/app/settings.h"
#include "editor/window/modelsettingsdialog.h"

#include "core/templates/packml/packmlmodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QStandardPaths>
#include <QTest>
#include <QUndoStack>
#include <QWidget>

using namespace editor;
using namespace packmldocktest;
using core::packml::Command;
using core::packml::Edition;
using core::packml::State;

class TestPackmlModelSettings : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void settingsWidgetInModelSettings();
};

void TestPackmlModelSettings::settingsWidgetInModelSettings()
{
    Document document(core::packml::newModel(Edition::Y2015));
    Settings settings;
    {
        ModelSettingsDialog dialog(document, settings);
        auto* edition = child<QComboBox>(dialog, "editionCombo");
        auto* hold = child<QCheckBox>(dialog, "holdInSuspendedCheck");
        auto* complete = child<QCheckBox>(dialog, "completeInSuspendedHeldCheck");
        QVERIFY(!hold->isChecked());
        QVERIFY(!complete->isEnabled()); // 2022 only
        const int y2022 = edition->findData(static_cast<int>(Edition::Y2022));
        edition->setCurrentIndex(y2022);
        emit edition->activated(y2022);
        QVERIFY(hold->isChecked()); // the edition's default
        QVERIFY(complete->isEnabled());
        complete->setChecked(true);
        auto* initial = child<QComboBox>(dialog, "initialStateCombo");
        initial->setCurrentIndex(initial->findText(QStringLiteral("Aborted")));
        child<QLineEdit>(dialog, "nameEdit")->setText(QStringLiteral("Capper"));
        dialog.accept();
    }
    const core::packml::Options options = config(document).options;
    QCOMPARE(options.edition, Edition::Y2022);
    QVERIFY(options.holdInSuspended);
    QVERIFY(options.completeInSuspendedHeld);
    QCOMPARE(config(document).initialState, State::Aborted);
    QCOMPARE(config(document).command(Command::Complete).condition, std::string("Cmd_Complete"));
    QCOMPARE(document.undoStack()->count(), 1); // one step for the dialog
    document.undoStack()->undo();
    QCOMPARE(config(document).options.edition, Edition::Y2015);
    QCOMPARE(config(document).initialState, State::Stopped);
    QVERIFY(document.model().settings().name != "Capper");

    // Nothing changed: nothing pushed.
    {
        ModelSettingsDialog dialog(document, settings);
        dialog.accept();
    }
    QCOMPARE(document.undoStack()->index(), 0);

    Document gemma;
    ModelSettingsDialog gemmaDialog(gemma, settings);
    QVERIFY(!gemmaDialog.findChild<QWidget*>(QStringLiteral("packmlSettings")));
}

QTEST_MAIN(TestPackmlModelSettings)
#include "test_packmlmodelsettings.moc"

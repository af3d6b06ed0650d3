#include "editor/app/examplemodels.h"

#include "core/formats/modelfiles.h"

#include <QCoreApplication>
#include <QFile>

namespace editor {

std::vector<ExampleModel> exampleModels()
{
    return {
        {QStringLiteral("drilling-cell.ggstudio.json"),
         QCoreApplication::translate("ExampleModels", "Drilling Cell"),
         QCoreApplication::translate("ExampleModels",
                                     "A machine that clamps, drills and marks parts: GEMMA states with four "
                                     "nested GRAFCETs, ready to simulate")},
        {QStringLiteral("drilling-cell-faulty.ggstudio.json"),
         QCoreApplication::translate("ExampleModels", "Drilling Cell with Mistakes"),
         QCoreApplication::translate("ExampleModels",
                                     "The same machine with one mistake for each check of the nested "
                                     "GRAFCETs, to see what the Problems panel reports")},
        {QStringLiteral("bottle-filler.ggstudio.json"),
         QCoreApplication::translate("ExampleModels", "Bottle Filler (PackML)"),
         QCoreApplication::translate("ExampleModels",
                                     "A PackML unit with Production and Manual modes and a GRAFCET in Resetting, "
                                     "Starting, Execute, Stopping and Aborting")},
    };
}

std::unique_ptr<core::Model> loadExampleModel(const ExampleModel& example, QString* error)
{
    QFile file(QStringLiteral(":/examples/") + example.fileName);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QCoreApplication::translate("ExampleModels", "The example %1 is missing from this build.")
                     .arg(example.fileName);
        return nullptr;
    }
    const QByteArray text = file.readAll();
    core::LoadedModel loaded =
        core::loadModelText(std::string_view(text.constData(), size_t(text.size())), example.fileName.toStdString());
    if (!loaded.ok()) {
        *error = QString::fromStdString(loaded.error.toString());
        return nullptr;
    }
    return std::move(loaded.model);
}

} // namespace editor

#include "editor/grafcet/grafcetclipboard.h"

#include "editor/docks/grafcetactionsmodel.h"

#include "core/formats/grafcetfragmentjson.h"

#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QStringList>

namespace editor {

namespace {

QString numbers(const std::vector<int>& steps)
{
    QStringList list;
    for (int step : steps)
        list << QString::number(step);
    return list.join(QStringLiteral(", "));
}

} // namespace

void GrafcetClipboard::put(const core::GrafcetFragment& fragment)
{
    auto* data = new QMimeData; // the clipboard owns it
    data->setData(kMimeType, QByteArray::fromStdString(core::saveGrafcetFragmentJson(fragment)));
    data->setText(plainText(fragment));
    QGuiApplication::clipboard()->setMimeData(data);
}

bool GrafcetClipboard::holdsFragment()
{
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    return data && data->hasFormat(kMimeType);
}

std::variant<core::GrafcetFragment, QString> GrafcetClipboard::fragment()
{
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    if (!data || !data->hasFormat(kMimeType))
        return tr("The clipboard holds no GRAFCET steps");
    const QByteArray bytes = data->data(kMimeType);
    auto result = core::loadGrafcetFragmentJson(std::string_view(bytes.constData(), std::size_t(bytes.size())));
    if (auto* fragment = std::get_if<core::GrafcetFragment>(&result))
        return std::move(*fragment);
    const core::JsonReadError& error = std::get<core::JsonReadError>(result);
    const QString where = QString::fromStdString(error.location);
    const QString what = QString::fromStdString(error.message);
    //: %1 what is wrong in the clipboard's data (in English), with where when known
    return tr("Nothing pasted: the GRAFCET steps on the clipboard are damaged (%1)")
        .arg(where.isEmpty() ? what : where + QStringLiteral(": ") + what);
}

QString GrafcetClipboard::plainText(const core::GrafcetFragment& fragment)
{
    QStringList lines;
    for (const core::GrafcetStep& step : fragment.steps) {
        const QString title = tr("Step %1").arg(step.number);
        lines << (step.comment.empty() ? title : title + QStringLiteral(" — ") + QString::fromStdString(step.comment));
        for (const core::GrafcetAction& action : step.actions)
            lines << QStringLiteral("    %1: %2").arg(GrafcetActionsModel::timingText(action.timing),
                                                     QString::fromStdString(action.text));
    }
    for (const core::GrafcetTransition& t : fragment.transitions)
        //: a transition copied as text: %1 its number, %2 and %3 the steps it links, %4 its receptivity
        lines << tr("T%1 (%2 → %3): %4")
                     .arg(t.number)
                     .arg(numbers(t.upstream), numbers(t.downstream), QString::fromStdString(t.receptivity));
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace editor

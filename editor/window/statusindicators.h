#pragma once

#include <QLabel>
#include <QWidget>

class QToolButton;

namespace editor {

class Document;
class VerificationRunner;

// The status bar's permanent fields: how many errors and warnings the model
// has (a click asks for the Problems dock), and the chart's zoom.
class ProblemCounter : public QWidget {
    Q_OBJECT

public:
    explicit ProblemCounter(Document& document, QWidget* parent = nullptr);

    int errorCount() const { return m_errors; }
    int warningCount() const { return m_warnings; }
    // The last verification's findings count too, said apart from the
    // checks' problems ("… · Verification: 1 warning"), "outdated" once
    // the model changed after it.
    void setVerification(const VerificationRunner* runner);
    int findingCount() const { return m_findings; }

signals:
    void clicked();

protected:
    void changeEvent(QEvent* event) override;

private:
    void recount();
    void retranslate();

    Document& m_document;
    const VerificationRunner* m_verification = nullptr;
    QToolButton* m_button;
    int m_errors = 0;
    int m_warnings = 0;
    int m_findings = 0;
    int m_findingErrors = 0;
    bool m_findingsStale = false;
};

class ZoomIndicator : public QWidget {
    Q_OBJECT

public:
    explicit ZoomIndicator(QWidget* parent = nullptr);

    void setZoom(double zoom); // 1.0 is 100 %
    QString text() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();

    QLabel* m_label;
    double m_zoom = 1.0;
};

// A label on a rounded yellow badge, like a highlighter mark: the status
// bar's "Simulation: editing locked". Painted rather than styled: a style
// sheet would put a QStyleSheetStyle (a CSS parser and a style of its own)
// under the widget on every start, for a badge that shows only while simulating.
class StatusBadge : public QLabel {
    Q_OBJECT

public:
    explicit StatusBadge(QWidget* parent = nullptr);

    static QColor badgeColor() { return QColor(0xff, 0xd8, 0x4d); }
    static QColor textColor() { return QColor(0x20, 0x24, 0x2a); }

protected:
    void paintEvent(QPaintEvent* event) override;
};

} // namespace editor

#include "editor/text/valueproblemtext.h"

#include <QCoreApplication>

namespace editor {

namespace {

// The translation context of the texts.
class ValueProblemText {
    Q_DECLARE_TR_FUNCTIONS(ValueProblemText)
};

QString integerText(const QString& value, const std::string& type)
{
    const QString name = QString::fromStdString(type);
    // English needs "an INT" but "a SINT": two texts, the same in most languages.
    if (type == "INT")
        //: %1: the value as written; %2: INT
        return ValueProblemText::tr("'%1' is not an %2 literal: write a whole number such as 42").arg(value, name);
    //: %1: the value as written; %2: an integer type other than INT (SINT, UDINT...)
    return ValueProblemText::tr("'%1' is not a %2 literal: write a whole number such as 42").arg(value, name);
}

} // namespace

QString valueProblemText(const core::ValueProblem& problem)
{
    using Kind = core::ValueProblem::Kind;
    const QString value = QString::fromStdString(problem.value);
    const QString type = QString::fromStdString(problem.type);
    switch (problem.kind) {
    case Kind::Spaces: return ValueProblemText::tr("'%1' has leading or trailing spaces").arg(value);
    case Kind::NotBool: return ValueProblemText::tr("'%1' is not a BOOL literal (TRUE or FALSE)").arg(value);
    case Kind::NotInteger: return integerText(value, problem.type);
    case Kind::NotReal:
        //: %1: the value as written; %2: REAL or LREAL
        return ValueProblemText::tr("'%1' is not a %2 literal: write a decimal number such as 1.5 or 2.0E3")
            .arg(value, type);
    case Kind::OutOfRange:
        //: %1: the value as written; %2: its IEC type; %3..%4: the type's range
        return ValueProblemText::tr("'%1' is out of range for %2 (%3..%4)")
            .arg(value, type, QString::fromStdString(problem.low), QString::fromStdString(problem.high));
    }
    return {};
}

} // namespace editor

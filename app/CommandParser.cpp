#include "CommandParser.h"

#include "Commands.h"

#include <QRegularExpression>

#include <cstdio>

namespace athlos::cli {

CommandParser::CommandParser(const QString& usage, const QString& description) : usage_(usage) {
    parser_.setApplicationDescription(description);
    parser_.addHelpOption();
    parser_.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
}

void CommandParser::addPositional(const QString& name, const QString& help) {
    parser_.addPositionalArgument(name, help);
}

std::optional<int> CommandParser::parse(const QStringList& args, int positionalMin, int positionalMax) {
    QStringList full = args;
    full[0] = QStringLiteral("athlos ") + args[0];
    if (!parser_.parse(full))
        return fail(parser_.errorText() + QStringLiteral(" (see: athlos ") + usage_ + QStringLiteral(" --help)"),
                    Usage);
    if (parser_.isSet(QStringLiteral("help"))) {
        QString help = parser_.helpText();
        help.replace(QRegularExpression(QStringLiteral("^Usage: [^\\n]*")), QStringLiteral("Usage: athlos ") + usage_);
        std::fputs(qUtf8Printable(help), stdout);
        return Ok;
    }
    const int n = int(parser_.positionalArguments().size());
    if (n < positionalMin || n > positionalMax)
        return fail(QStringLiteral("usage: athlos %1 (see --help)").arg(usage_), Usage);
    return std::nullopt;
}

}  // namespace athlos::cli

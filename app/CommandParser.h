#pragma once
// Shared QCommandLineParser set-up for the sub-commands: --help on every command, errors that name
// the option, and positional-argument count checks.
#include <QCommandLineParser>
#include <QStringList>
#include <optional>

namespace athlos::cli {

class CommandParser {
public:
    // usage: e.g. "import <project> <file>", description: one paragraph.
    CommandParser(const QString& usage, const QString& description);
    QCommandLineParser& parser() { return parser_; }
    void addPositional(const QString& name, const QString& help);
    void addOption(const QCommandLineOption& option) { parser_.addOption(option); }

    // Parses args (args[0] is the command name). Returns an exit code to stop with (help printed
    // or usage error), or nothing to continue. positionalMin/Max bound the positional arguments.
    std::optional<int> parse(const QStringList& args, int positionalMin, int positionalMax);
    QStringList positional() const { return parser_.positionalArguments(); }

private:
    QCommandLineParser parser_;
    QString usage_;
};

}  // namespace athlos::cli

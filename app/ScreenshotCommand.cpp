// athlos screenshot
#include "CommandParser.h"
#include "Commands.h"

#include "ui/UiEntry.h"

#include <cstdio>

namespace athlos::cli {

int cmdScreenshot(const QStringList& args) {
    const QStringList views = ui::screenshotViews();
    CommandParser p(QStringLiteral("screenshot <project> --view <name> --to <file.png>"),
                    QStringLiteral("Render a view of the project offscreen into a PNG (for CI and documentation)."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("view"), QStringLiteral("One of: ") + views.join(QStringLiteral(", ")),
                 QStringLiteral("name"), QStringLiteral("main")});
    p.addOption({QStringLiteral("to"), QStringLiteral("PNG file to write."), QStringLiteral("file")});
    p.addOption({QStringLiteral("size"), QStringLiteral("Window size WxH (default 1280x800)."), QStringLiteral("WxH"),
                 QStringLiteral("1280x800")});
    p.addOption(
        {QStringLiteral("list"), QStringLiteral("Print the view names, one per line (for scripts), and exit.")});
    if (auto code = p.parse(args, 0, 1)) return *code;
    if (p.parser().isSet(QStringLiteral("list"))) {
        for (const QString& view : views) std::printf("%s\n", qUtf8Printable(view));
        return Ok;
    }
    if (p.positional().isEmpty()) return fail(QStringLiteral("screenshot needs a project (or --list)"), Usage);
    const QString to = p.parser().value(QStringLiteral("to"));
    if (to.isEmpty()) return fail(QStringLiteral("screenshot needs --to <file.png>"), Usage);
    const QStringList wh = p.parser().value(QStringLiteral("size")).split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const QSize size(wh.value(0).toInt(&okW), wh.value(1).toInt(&okH));
    if (wh.size() != 2 || !okW || !okH || size.width() < 200 || size.height() < 150)
        return fail(
            QStringLiteral("--size '%1': expected WxH, at least 200x150").arg(p.parser().value(QStringLiteral("size"))),
            Usage);
    if (Status s = ui::renderScreenshot(p.positional()[0], p.parser().value(QStringLiteral("view")), to, size); !s)
        return fail(s.message());
    return Ok;
}

}  // namespace athlos::cli

#pragma once
// Tools (wizards, analysis windows) register themselves here and appear in the main window's
// menus; screenshot views register a renderer. This keeps MainWindow free of per-tool code:
// each tool is one file that calls ATHLOS_REGISTER_TOOL / ATHLOS_REGISTER_VIEW.
#include "core/util/Expected.h"

#include <QString>
#include <functional>
#include <vector>

namespace athlos {
class Project;
}

namespace athlos::ui {

class Workspace;

struct ToolEntry {
    QString id;        // stable, e.g. "position-filter-wizard"
    const char* text;  // menu text, a QT_TRANSLATE_NOOP("Tools", "...") literal (translated when shown)
    const char* menu;  // "Processing", "Positioning", "Inertial", "View"… (also QT_TRANSLATE_NOOP("Tools", …))
    std::function<void(Workspace&)> launch;
};

// A screenshot view: prepares the (offscreen, already sized) main window for `athlos screenshot
// --view <name>` through its Workspace: shows the right panels with data from the project. Error
// if the project has no suitable data for the view.
struct ViewEntry {
    QString name;  // e.g. "playback"
    std::function<Status(Workspace&)> prepare;
    // Whether the project has the data the view shows; unset: prepare() decides (and says why
    // not). A built-in view may hand over to a registered one that has data (e.g. `trajectory`
    // to `team`).
    std::function<bool(const Project&)> hasData = {};
};

void registerTool(ToolEntry entry);
const std::vector<ToolEntry>& registeredTools();
void registerView(ViewEntry entry);
const std::vector<ViewEntry>& registeredViews();

}  // namespace athlos::ui

#define ATHLOS_UI_CONCAT2(a, b) a##b
#define ATHLOS_UI_CONCAT(a, b) ATHLOS_UI_CONCAT2(a, b)
// At namespace scope in a .cpp of athlos_ui: ATHLOS_REGISTER_TOOL({"id", QT_TRANSLATE_NOOP(...), ..., launch});
#define ATHLOS_REGISTER_TOOL(...) \
    static const bool ATHLOS_UI_CONCAT(athlosTool_, __LINE__) = (::athlos::ui::registerTool(__VA_ARGS__), true)
#define ATHLOS_REGISTER_VIEW(...) \
    static const bool ATHLOS_UI_CONCAT(athlosView_, __LINE__) = (::athlos::ui::registerView(__VA_ARGS__), true)

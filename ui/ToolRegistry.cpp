#include "ui/ToolRegistry.h"

namespace athlos::ui {
namespace {

// Function-local statics: registration runs during static initialisation of other files.
std::vector<ToolEntry>& tools() {
    static std::vector<ToolEntry> list;
    return list;
}
std::vector<ViewEntry>& views() {
    static std::vector<ViewEntry> list;
    return list;
}

}  // namespace

void registerTool(ToolEntry entry) { tools().push_back(std::move(entry)); }
const std::vector<ToolEntry>& registeredTools() { return tools(); }
void registerView(ViewEntry entry) { views().push_back(std::move(entry)); }
const std::vector<ViewEntry>& registeredViews() { return views(); }

}  // namespace athlos::ui

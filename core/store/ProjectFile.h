#pragma once
// The HDF5 side of a project. Layout (format_version 2; version 1 stored strings as variable-length
// strings and had no checksums; it is read and upgraded on save):
//   /                       attrs: format="athlos", format_version, app_version, created, modified, sport, extra (JSON)
//   /geometry/<name>        attr json
//   /annotation_classes     attr json (array) on /
//   /pipelines              attr json (array) on /
//   /recordings/<rec>       attr metadata (JSON)
//   /recordings/<rec>/<stream>   attrs: type="stream", kind, frame, columns (JSON [{name,unit}]),
//                                attributes (JSON), provenance (JSON), rows, t_begin, t_end, content_hash
//                           datasets: t (N, float64), data (N×C, float64), chunked + shuffle + deflate + Fletcher32
//   /recordings/<rec>/<table>    attrs: type="table", kind, attributes, provenance, columns (JSON)
//                           datasets: one per column (float64 or fixed-length UTF-8 string)
//   /annotations/<rec>      datasets: label, annotator, source (strings), t_start, t_end, confidence (float64)
#include "core/model/Project.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QString>

namespace athlos {

class ProjectFile {
public:
    // Reads structure and metadata of path into project; streams get lazy loaders on path.
    // Refuses: missing file, not HDF5, not an Athlos project, newer format_version, damaged
    // structure — each with a message naming the file.
    static Status read(const QString& path, Project& project);

    // Reads the whole file (structure and every sample) in a child process; refuses a damaged file
    // with the reason, even one that crashes or hangs the HDF5 library. Files this process wrote
    // or checked before, unchanged since, pass at once.
    static Status check(const QString& path);

    // Writes the complete project to path (which must not be the file streams are loaded from).
    // Unloaded streams are copied from their FileSource without decoding. Not atomic by itself:
    // Project::save() writes to a temporary file and renames.
    static Status write(const Project& project, const QString& path, const Progress& progress = {});

    // After a successful write+rename: point every stream's lazy loader at its place in path.
    static void rebind(Project& project, const QString& path);

    // Loads the samples of the stream stored at group in file.
    static Expected<StreamData> loadStream(const QString& file, const QString& group, int columns);
};

}  // namespace athlos

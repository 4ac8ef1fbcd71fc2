#pragma once
// The processor interface: the unit of work that the GUI, the CLI and pipelines all run the same way.
//
// A processor reads input streams/tables (read-only), computes, and returns new items. It never
// writes into the project itself: the ProcessorRunner validates parameters and inputs, calls run(),
// attaches provenance and stores the outputs only when run() succeeded and was not cancelled.
#include "core/model/Project.h"
#include "core/processing/ParameterSpec.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace athlos {

struct InputSpec {
    QString name;        // role, e.g. "signal", "tdoa", "beacons"
    QStringList kinds;   // accepted kinds; empty = any stream
    bool table = false;  // a table instead of a stream
    bool optional = false;
    QString help;
};

struct OutputSpec {
    QString kind;  // kind of the produced stream/table; empty = the kind of the first input
    bool table = false;
    QString suffix;  // empty for the main output; else stored as "<output>-<suffix>"
    QString help;
    // Predicted annotations (intervals/instants with label and confidence) added to the
    // recording of --output instead of an item; kind and table are then ignored.
    bool annotations = false;
};

// One produced item. The runner names it after --output (plus suffix) and adds provenance.
//
// Annotations go into Recording::annotations of the output's recording. The runner sets each
// annotation's source to the processor id and its annotator to the output path ("rec/name" plus
// suffix), so a re-run replaces exactly the annotations of the same processor and output, and
// records the run's provenance in the recording's metadata under "annotation_provenance"/<path>.
struct ProcessorOutput {
    QString suffix;
    std::variant<Stream, Table, Annotations> item;
};

// One input stream of a run with its samples loaded (RunContext::samples()).
struct InputSamples {
    const Stream* stream = nullptr;
    std::shared_ptr<const StreamData> data;
    QString path;  // "rec/item", as given to the run
    QString role;  // InputSpec::name

    const StreamInfo& info() const { return stream->info(); }
    // An error about this input: "input 'rec/imu' (signal): <message>" (the runner prefixes the
    // processor id), the form the runner uses for its own input checks.
    Error error(const QString& message) const;
    // The nominal sampling interval (median step, s), or an error naming the input when it has
    // fewer than 2 samples or no positive step.
    Expected<double> samplingInterval() const;
};

class RunContext {
public:
    RunContext(const Project& project, QList<InputSpec> inputSpecs, std::vector<const Stream*> streams,
               std::vector<const Table*> tables, std::vector<QString> inputPaths, QVariantMap parameters,
               QString outputPath, Progress progress);

    const Project& project() const { return project_; }
    // Inputs in the order of Processor::inputs(); absent optional inputs are nullptr.
    const Stream* stream(int index) const;
    const Table* table(int index) const;
    const QString& inputPath(int index) const { return inputPaths_.at(index); }
    int inputCount() const { return static_cast<int>(inputPaths_.size()); }
    // The role of input `index` (InputSpec::name), e.g. "signal".
    QString inputRole(int index) const;
    const QString& outputPath() const { return outputPath_; }

    // The samples of input stream `index` (loaded on first use, shared with other readers). The
    // error names the input and the stream: "input 'rec/imu' (signal): cannot read its samples:
    // <reason>" or "input 'signal' was not given"; the runner prefixes the processor id.
    Expected<InputSamples> samples(int index) const;
    // The table of input `index`, or the same kind of error when it was not given.
    Expected<const Table*> requireTable(int index) const;
    // An error about input `index` in the same form: "input 'rec/imu' (signal): <message>".
    Error inputError(int index, const QString& message) const;

    const QVariantMap& parameters() const { return parameters_; }
    bool has(const QString& name) const { return parameters_.contains(name); }
    double number(const QString& name) const { return parameters_.value(name).toDouble(); }
    int integer(const QString& name) const { return parameters_.value(name).toInt(); }
    bool flag(const QString& name) const { return parameters_.value(name).toBool(); }
    QString text(const QString& name) const { return parameters_.value(name).toString(); }

    // Records a stream or table read besides the declared inputs (e.g. the other athletes' streams of a
    // session, a noise-profile table), "rec/name" with its content hash now, so that its provenance lists
    // it and `athlos batch` sees it change. Appended to the run's provenance inputs after the declared
    // ones; a path is recorded once.
    void recordRead(const QString& path, const QByteArray& hash) const;
    const std::vector<ProvenanceInput>& extraReads() const { return extraReads_; }

    const Progress& progress() const { return progress_; }
    void report(double fraction, const QString& message = {}) const { progress_.report(fraction, message); }
    bool isCancelled() const { return progress_.isCancelled(); }

private:
    const Project& project_;
    QList<InputSpec> inputSpecs_;
    std::vector<const Stream*> streams_;
    std::vector<const Table*> tables_;
    std::vector<QString> inputPaths_;
    QVariantMap parameters_;
    QString outputPath_;
    Progress progress_;
    mutable std::vector<ProvenanceInput> extraReads_;
};

class Processor {
public:
    virtual ~Processor() = default;

    virtual QString id() const = 0;    // stable, used on the CLI: "resample"
    virtual QString name() const = 0;  // translated display name
    virtual QString description() const = 0;
    virtual QString version() const = 0;  // bump when results change
    virtual ParameterSpecs parameters() const = 0;
    virtual QList<InputSpec> inputs() const = 0;
    virtual QList<OutputSpec> outputs() const = 0;

    // Optional hook: the checks and preparation that need the inputs (e.g. cut-off below Nyquist,
    // required columns present), shared by validate() and run(). A processor with a typed plan
    // keeps it in a function of its own and returns statusOf(plan(context)) here. Default: accepts.
    virtual Status prepare(const RunContext&) const { return {}; }
    // Called by the runner before run(); the default is prepare().
    virtual Status validate(const RunContext& context) const { return prepare(context); }

    virtual Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const = 0;

    QJsonObject describe() const;  // schema as JSON (athlos processors --json)
};

// Error returned by run() when it noticed cancellation.
inline Error cancelledError() { return makeError(QStringLiteral("cancelled")); }

}  // namespace athlos

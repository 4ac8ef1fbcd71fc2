#pragma once
// The samples of a stream: strictly increasing times (s) and an N×C row-major block of values.
#include <Eigen/Core>
#include <QByteArray>
#include <cstddef>
#include <vector>

namespace athlos {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct StreamData {
    std::vector<double> t;       // seconds, strictly increasing
    std::vector<double> values;  // row-major, t.size() × columns
    int columns = 0;

    StreamData() = default;
    StreamData(std::size_t rows, int cols) : t(rows), values(rows * static_cast<std::size_t>(cols)), columns(cols) {}

    std::size_t rows() const { return t.size(); }
    double& at(std::size_t row, int col) { return values[row * columns + col]; }
    double at(std::size_t row, int col) const { return values[row * columns + col]; }

    Eigen::Map<RowMatrix> matrix() { return {values.data(), Eigen::Index(rows()), columns}; }
    Eigen::Map<const RowMatrix> matrix() const { return {values.data(), Eigen::Index(rows()), columns}; }
    // Column c as a strided vector (no copy).
    Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>> column(int c) const {
        return {values.data() + c, Eigen::Index(rows()), Eigen::InnerStride<>(columns)};
    }
    Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>> column(int c) {
        return {values.data() + c, Eigen::Index(rows()), Eigen::InnerStride<>(columns)};
    }

    // Index of the first sample whose time is not strictly after its predecessor, or -1.
    long long firstNonIncreasing() const;
    // Median sampling interval (s; math::upperMedian of the steps); 0 for fewer than two samples.
    double medianInterval() const;
    // SHA-256 over t and values (little-endian float64), hex. Written with every stream so that
    // provenance can name exact inputs without reading samples back.
    QByteArray contentHash() const;
};

}  // namespace athlos

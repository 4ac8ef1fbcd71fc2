#pragma once
// Rauch–Tung–Striebel smoothing over a stored forward pass (thesis §4.1.2), and the fixed-lag
// variant that uses only observations up to t + lag.
//
// The gain is written with the cross-covariance C_{k+1} = cov(x_k, x_{k+1} | y_{1:k}) that every
// filter returns from predict(): J_k = C_{k+1} P_{k+1|k}⁻¹. For the EKF C = P_{k|k} Φᵀ, which gives
// the textbook J_k = P_{k|k} Φᵀ P_{k+1|k}⁻¹; for the UKF/SRUKF it is the unscented RTS smoother.
//   x_{k|N} = x_{k|k} + J_k (x_{k+1|N} − x_{k+1|k})
//   P_{k|N} = P_{k|k} + J_k (P_{k+1|N} − P_{k+1|k}) J_kᵀ
// Rejected outliers never entered x_{k|k}, so the smoother ignores them as the thesis requires.
#include "core/estimation/KalmanTypes.h"

#include <Eigen/Cholesky>
#include <cstddef>
#include <vector>

namespace athlos::estimation {

template <int N>
struct SmootherNode {
    double t = 0.0;
    Vector<N> xf;     // x_{k|k}  (after any update at t)
    Matrix<N, N> Pf;  // P_{k|k}
    Vector<N> xp;     // x_{k|k−1} (prediction into t from the previous node)
    Matrix<N, N> Pp;  // P_{k|k−1}
    Matrix<N, N> C;   // cov(x_{k−1}, x_k | y_{1:k−1}) from the prediction into this node
};

template <MotionModel Model>
class RtsSmoother {
public:
    static constexpr int N = Model::kStateDim;
    using Node = SmootherNode<N>;
    struct Estimate {
        Vector<N> x;
        Matrix<N, N> P;
    };

    explicit RtsSmoother(const Model& model) : model_(model) {}

    // One backward step: from the smoothed estimate at node k+1 to node k.
    Estimate step(const Node& k, const Node& next, const Estimate& smoothedNext) const {
        const Matrix<N, N> J = gain(next);
        Estimate e;
        e.x = k.xf + J * model_.difference(smoothedNext.x, next.xp);
        model_.normalize(e.x);
        e.P = k.Pf + J * (smoothedNext.P - next.Pp) * J.transpose();
        e.P = 0.5 * (e.P + e.P.transpose());
        return e;
    }

    // Full RTS over all nodes (in place of the filtered values: xf/Pf become x_{k|N}/P_{k|N}).
    void smoothAll(std::vector<Node>& nodes) const {
        if (nodes.size() < 2) return;
        Estimate s{nodes.back().xf, nodes.back().Pf};
        for (std::size_t k = nodes.size() - 1; k-- > 0;) {
            s = step(nodes[k], nodes[k + 1], s);
            nodes[k].xf = s.x;
            nodes[k].Pf = s.P;
        }
    }

    // Fixed-interval smoothing of node `target` using the nodes up to `horizon` (≥ target) only:
    // the fixed-lag estimate x_{target | horizon}.
    Estimate smoothAt(const std::vector<Node>& nodes, std::size_t target, std::size_t horizon) const {
        Estimate s{nodes[horizon].xf, nodes[horizon].Pf};
        for (std::size_t k = horizon; k > target; --k) s = step(nodes[k - 1], nodes[k], s);
        return s;
    }

private:
    Matrix<N, N> gain(const Node& next) const {
        // P_{k+1|k} is symmetric positive (semi)definite; LDLT copes with the tiny pivots of a
        // constrained state (augmented model: φ, ω rows driven by the track only).
        const Eigen::LDLT<Matrix<N, N>> ldlt(next.Pp + 1e-12 * Matrix<N, N>::Identity());
        return ldlt.solve(next.C.transpose()).transpose();
    }

    const Model& model_;
};

}  // namespace athlos::estimation

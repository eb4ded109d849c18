#include "tumble/sweep/run_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tumble/math/local_minimum.hpp"
#include "tumble/math/sign_change.hpp"

namespace tumble {

namespace {

// Gauss-Lobatto's five-point rule on [0, 1]: both ends, the middle and 1/2 -+ sqrt(21)/14.
constexpr std::array<double, PieceSamples::kNodes> kLobattoWeights = {
    1.0 / 20, 49.0 / 180, 16.0 / 45, 49.0 / 180, 1.0 / 20};

// Whether the parabola through (x_end, f_end), (x_next, f_next), (x_far, f_far) has a maximum
// strictly between x_end and x_next: then a function highest at the end sample of a piece peaks
// inside, not beyond the end.
bool peaks_between(double x_end, double f_end, double x_next, double f_next, double x_far,
                   double f_far) {
  const double slope_near = (f_next - f_end) / (x_next - x_end);
  const double slope_far = (f_far - f_next) / (x_far - x_next);
  const double curvature = (slope_far - slope_near) / (x_far - x_end);  // f'' / 2
  if (!(curvature < 0.0)) return false;
  // f = f_end + slope_near (x - x_end) + curvature (x - x_end) (x - x_next): f' = 0 at
  const double vertex = 0.5 * (x_end + x_next) - slope_near / (2.0 * curvature);
  return (vertex - x_end) * (vertex - x_next) < 0.0;
}

}  // namespace

PieceSamples PieceSamples::on(double a, double b, bool fresh_start, Need need) {
  PieceSamples samples;
  samples.fresh_start = fresh_start;
  samples.t.fill(a);
  const double h = b - a;
  if (!(h > 0.0)) {
    samples.count = 1;
  } else if (need == Need::Ends) {
    samples.t[1] = b;
    samples.count = 2;
  } else if (need == Need::Mean) {
    static const double inner = std::sqrt(21.0) / 14.0;
    samples.t = {a, a + (0.5 - inner) * h, a + 0.5 * h, a + (0.5 + inner) * h, b};
    samples.count = 5;
  } else {
    samples.t[1] = a + 0.5 * h;
    samples.t[2] = b;
    samples.count = 3;
  }
  return samples;
}

RunReduction::RunReduction(ReductionKind kind, const std::string& text,
                           std::span<const BoundExpression::Variable> variables)
    : kind_(kind), value_(text, variables) {
  if (kind == ReductionKind::First || kind == ReductionKind::Count) {
    if (const auto comparison = split_comparison(text)) {
      margin_ = std::make_unique<BoundExpression>(comparison->margin(), variables);
    }
  }
}

void RunReduction::start() {
  sampled_ = false;
  has_best_ = false;
  integral_ = covered_ = 0.0;
  turns_ = 0.0;
}

void RunReduction::observe_row() {
  last_ = value_.evaluate();
  sampled_ = true;
}

void RunReduction::take_sample(int k) {
  values_[static_cast<std::size_t>(k)] = value_.evaluate();
  if (margin_) margins_[static_cast<std::size_t>(k)] = margin_->evaluate();
}

void RunReduction::observe_piece(const PieceSamples& samples, FunctionRef<void(double t)> load) {
  if (!samples.fresh_start) {
    values_[0] = last_;
    margins_[0] = last_margin_;
  }
  switch (kind_) {
    case ReductionKind::Max:
    case ReductionKind::Min:
    case ReductionKind::TimeOfMax:
      observe_extremum(samples, load);
      break;
    case ReductionKind::Mean:
      observe_mean(samples);
      break;
    case ReductionKind::First:
    case ReductionKind::Count:
      observe_turns(samples, load);
      break;
    default:
      break;
  }
  const auto last = static_cast<std::size_t>(samples.count - 1);
  last_ = values_[last];
  last_margin_ = margins_[last];
  sampled_ = true;
}

void RunReduction::consider(double t, double value) {
  const bool better = kind_ == ReductionKind::Min ? value < best_ : value > best_;
  if (!has_best_ || better) {
    best_ = value;
    t_best_ = t;
    has_best_ = true;
  }
}

void RunReduction::observe_extremum(const PieceSamples& samples, FunctionRef<void(double t)> load) {
  for (int k = samples.fresh_start ? 0 : 1; k < samples.count; ++k) {
    consider(samples.t[static_cast<std::size_t>(k)], values_[static_cast<std::size_t>(k)]);
  }
  const auto n = static_cast<std::size_t>(samples.count);
  if (n < 3) return;
  // Maxima of sign * value.
  const double sign = kind_ == ReductionKind::Min ? -1.0 : 1.0;
  const auto& t = samples.t;
  std::array<double, PieceSamples::kNodes> f{};
  for (std::size_t k = 0; k < n; ++k) {
    f[k] = sign * values_[k];
    if (!std::isfinite(f[k])) return;
  }
  const auto i = static_cast<std::size_t>(std::max_element(f.begin(), f.begin() + n) - f.begin());
  // Where the function is highest between samples: beside the highest sample, inside the piece.
  double lo = 0.0, hi = 0.0, lower = 0.0;
  if (i == 0) {
    if (!peaks_between(t[0], f[0], t[1], f[1], t[2], f[2])) return;
    lo = t[0];
    hi = t[1];
    lower = f[1];
  } else if (i == n - 1) {
    if (!peaks_between(t[i], f[i], t[i - 1], f[i - 1], t[i - 2], f[i - 2])) return;
    lo = t[i - 1];
    hi = t[i];
    lower = f[i - 1];
  } else {
    lo = t[i - 1];
    hi = t[i + 1];
    lower = std::min(f[i - 1], f[i + 1]);
  }
  // A peak between two samples rises above the higher by less than the higher rises above the
  // lower: a piece that cannot beat the best so far is not searched. Nor one whose samples agree
  // to round-off (a conserved E): there is nothing between them to find.
  const double rise = f[i] - lower;
  if (f[i] + rise < sign * best_ ||
      rise <= 8.0 * std::numeric_limits<double>::epsilon() * std::abs(f[i])) {
    return;
  }
  const LocalMinimum peak = local_minimum(lo, hi, t[i], -f[i], [&](double at) {
    load(at);
    return -sign * value_.evaluate();
  });
  consider(peak.x, -sign * peak.value);
}

void RunReduction::observe_mean(const PieceSamples& samples) {
  if (samples.count != PieceSamples::kNodes) return;  // no width (a mean's pieces have 5 samples)
  double sum = 0.0;
  for (std::size_t k = 0; k < kLobattoWeights.size(); ++k) sum += kLobattoWeights[k] * values_[k];
  const double h = samples.t.back() - samples.t.front();
  integral_ += h * sum;
  covered_ += h;
}

void RunReduction::observe_turns(const PieceSamples& samples, FunctionRef<void(double t)> load) {
  const auto& t = samples.t;
  for (int k = samples.fresh_start ? 0 : 1; k < samples.count; ++k) {
    const auto j = static_cast<std::size_t>(k);
    const bool holds = values_[j] != 0.0;
    // At a fresh start, before it: the state before the jump (none at the run's start).
    const bool held = j == 0 ? sampled_ && last_ != 0.0 : values_[j - 1] != 0.0;
    if (!holds || held) continue;
    double at = t[j];  // the run's start, or the jump's instant
    if (j > 0) {
      const double m_lo = margins_[j - 1], m_hi = margins_[j];
      double lo = t[j - 1], hi = t[j];
      if (margin_ && m_lo == 0.0) {
        at = lo;  // A - B is zero where it did not yet hold (A > B): it holds just after
      } else if (margin_ && std::isfinite(m_lo) && std::isfinite(m_hi) &&
                 ((m_lo < 0.0) != (m_hi < 0.0) || m_hi == 0.0)) {
        at = sign_change_in(lo, hi, m_lo, m_hi, [&](double c) {
          load(c);
          return margin_->evaluate();
        });
      } else {
        // A condition of && or ||, or a margin that does not say: by bisection on its truth.
        for (int iteration = 0; iteration < 200; ++iteration) {
          const double floor = 4.0 * std::numeric_limits<double>::epsilon() *
                               std::max({1.0, std::abs(lo), std::abs(hi)});
          if (hi - lo <= floor) break;
          const double middle = lo + 0.5 * (hi - lo);
          load(middle);
          (value_.evaluate() != 0.0 ? hi : lo) = middle;
        }
        at = hi;
      }
    }
    if (turns_ == 0.0) turned_at_ = at;
    ++turns_;
  }
}

double RunReduction::result() const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (!sampled_) return nan;
  switch (kind_) {
    case ReductionKind::Final:
      return last_;
    case ReductionKind::Max:
    case ReductionKind::Min:
      return best_;
    case ReductionKind::TimeOfMax:
      return t_best_;
    case ReductionKind::Mean:
      return covered_ > 0.0 ? integral_ / covered_ : last_;
    case ReductionKind::First:
      return turns_ > 0.0 ? turned_at_ : nan;
    case ReductionKind::Count:
      return turns_;
    default:
      return nan;
  }
}

}  // namespace tumble

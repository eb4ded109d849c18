#include "tumble/integrators/dop853.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

namespace {

// The coefficients of DOP853 as published with Hairer and Wanner's code (Hairer-Norsett-Wanner I,
// section II.10), named a<i>_<j> = a_ij for stage i (1-based; stage 13 is f at the new state,
// stages 14..16 are the continuous extension's). Zero entries are left out of the sums below.
constexpr double c2 = 0.526001519587677318785587544488e-01;
constexpr double c3 = 0.789002279381515978178381316732e-01;
constexpr double c4 = 0.118350341907227396726757197510e+00;
constexpr double c5 = 0.281649658092772603273242802490e+00;
constexpr double c6 = 0.333333333333333333333333333333e+00;
constexpr double c7 = 0.25e+00;
constexpr double c8 = 0.307692307692307692307692307692e+00;
constexpr double c9 = 0.651282051282051282051282051282e+00;
constexpr double c10 = 0.6e+00;
constexpr double c11 = 0.857142857142857142857142857142e+00;
constexpr double c14 = 0.1e+00;
constexpr double c15 = 0.2e+00;
constexpr double c16 = 0.777777777777777777777777777778e+00;

constexpr double b1 = 5.42937341165687622380535766363e-2;
constexpr double b6 = 4.45031289275240888144113950566e0;
constexpr double b7 = 1.89151789931450038304281599044e0;
constexpr double b8 = -5.8012039600105847814672114227e0;
constexpr double b9 = 3.1116436695781989440891606237e-1;
constexpr double b10 = -1.52160949662516078556178806805e-1;
constexpr double b11 = 2.01365400804030348374776537501e-1;
constexpr double b12 = 4.47106157277725905176885569043e-2;

constexpr double bhh1 = 0.244094488188976377952755905512e+00;
constexpr double bhh2 = 0.733846688281611857341361741547e+00;
constexpr double bhh3 = 0.220588235294117647058823529412e-01;

constexpr double er1 = 0.1312004499419488073250102996e-01;
constexpr double er6 = -0.1225156446376204440720569753e+01;
constexpr double er7 = -0.4957589496572501915214079952e+00;
constexpr double er8 = 0.1664377182454986536961530415e+01;
constexpr double er9 = -0.3503288487499736816886487290e+00;
constexpr double er10 = 0.3341791187130174790297318841e+00;
constexpr double er11 = 0.8192320648511571246570742613e-01;
constexpr double er12 = -0.2235530786388629525884427845e-01;

constexpr double a2_1 = 5.26001519587677318785587544488e-2;
constexpr double a3_1 = 1.97250569845378994544595329183e-2;
constexpr double a3_2 = 5.91751709536136983633785987549e-2;
constexpr double a4_1 = 2.95875854768068491816892993775e-2;
constexpr double a4_3 = 8.87627564304205475450678981324e-2;
constexpr double a5_1 = 2.41365134159266685502369798665e-1;
constexpr double a5_3 = -8.84549479328286085344864962717e-1;
constexpr double a5_4 = 9.24834003261792003115737966543e-1;
constexpr double a6_1 = 3.7037037037037037037037037037e-2;
constexpr double a6_4 = 1.70828608729473871279604482173e-1;
constexpr double a6_5 = 1.25467687566822425016691814123e-1;
constexpr double a7_1 = 3.7109375e-2;
constexpr double a7_4 = 1.70252211019544039314978060272e-1;
constexpr double a7_5 = 6.02165389804559606850219397283e-2;
constexpr double a7_6 = -1.7578125e-2;
constexpr double a8_1 = 3.70920001185047927108779319836e-2;
constexpr double a8_4 = 1.70383925712239993810214054705e-1;
constexpr double a8_5 = 1.07262030446373284651809199168e-1;
constexpr double a8_6 = -1.53194377486244017527936158236e-2;
constexpr double a8_7 = 8.27378916381402288758473766002e-3;
constexpr double a9_1 = 6.24110958716075717114429577812e-1;
constexpr double a9_4 = -3.36089262944694129406857109825e0;
constexpr double a9_5 = -8.68219346841726006818189891453e-1;
constexpr double a9_6 = 2.75920996994467083049415600797e+1;
constexpr double a9_7 = 2.01540675504778934086186788979e+1;
constexpr double a9_8 = -4.34898841810699588477366255144e+1;
constexpr double a10_1 = 4.77662536438264365890433908527e-1;
constexpr double a10_4 = -2.48811461997166764192642586468e0;
constexpr double a10_5 = -5.90290826836842996371446475743e-1;
constexpr double a10_6 = 2.12300514481811942347288949897e+1;
constexpr double a10_7 = 1.52792336328824235832596922938e+1;
constexpr double a10_8 = -3.32882109689848629194453265587e+1;
constexpr double a10_9 = -2.03312017085086261358222928593e-2;
constexpr double a11_1 = -9.3714243008598732571704021658e-1;
constexpr double a11_4 = 5.18637242884406370830023853209e0;
constexpr double a11_5 = 1.09143734899672957818500254654e0;
constexpr double a11_6 = -8.14978701074692612513997267357e0;
constexpr double a11_7 = -1.85200656599969598641566180701e+1;
constexpr double a11_8 = 2.27394870993505042818970056734e+1;
constexpr double a11_9 = 2.49360555267965238987089396762e0;
constexpr double a11_10 = -3.0467644718982195003823669022e0;
constexpr double a12_1 = 2.27331014751653820792359768449e0;
constexpr double a12_4 = -1.05344954667372501984066689879e+1;
constexpr double a12_5 = -2.00087205822486249909675718444e0;
constexpr double a12_6 = -1.79589318631187989172765950534e+1;
constexpr double a12_7 = 2.79488845294199600508499808837e+1;
constexpr double a12_8 = -2.85899827713502369474065508674e0;
constexpr double a12_9 = -8.87285693353062954433549289258e0;
constexpr double a12_10 = 1.23605671757943030647266201528e+1;
constexpr double a12_11 = 6.43392746015763530355970484046e-1;

constexpr double a14_1 = 5.61675022830479523392909219681e-2;
constexpr double a14_7 = 2.53500210216624811088794765333e-1;
constexpr double a14_8 = -2.46239037470802489917441475441e-1;
constexpr double a14_9 = -1.24191423263816360469010140626e-1;
constexpr double a14_10 = 1.5329179827876569731206322685e-1;
constexpr double a14_11 = 8.20105229563468988491666602057e-3;
constexpr double a14_12 = 7.56789766054569976138603589584e-3;
constexpr double a14_13 = -8.298e-3;
constexpr double a15_1 = 3.18346481635021405060768473261e-2;
constexpr double a15_6 = 2.83009096723667755288322961402e-2;
constexpr double a15_7 = 5.35419883074385676223797384372e-2;
constexpr double a15_8 = -5.49237485713909884646569340306e-2;
constexpr double a15_11 = -1.08347328697249322858509316994e-4;
constexpr double a15_12 = 3.82571090835658412954920192323e-4;
constexpr double a15_13 = -3.40465008687404560802977114492e-4;
constexpr double a15_14 = 1.41312443674632500278074618366e-1;
constexpr double a16_1 = -4.28896301583791923408573538692e-1;
constexpr double a16_6 = -4.69762141536116384314449447206e0;
constexpr double a16_7 = 7.68342119606259904184240953878e0;
constexpr double a16_8 = 4.06898981839711007970213554331e0;
constexpr double a16_9 = 3.56727187455281109270669543021e-1;
constexpr double a16_13 = -1.39902416515901462129418009734e-3;
constexpr double a16_14 = 2.9475147891527723389556272149e0;
constexpr double a16_15 = -9.15095847217987001081870187138e0;

// Dense-output weights d<j>_<i>: r_j = h sum_i d_ji k_i for j = 4..7 (Hairer's CONT(5..8)).
constexpr double d4_1 = -0.84289382761090128651353491142e+01;
constexpr double d4_6 = 0.56671495351937776962531783590e+00;
constexpr double d4_7 = -0.30689499459498916912797304727e+01;
constexpr double d4_8 = 0.23846676565120698287728149680e+01;
constexpr double d4_9 = 0.21170345824450282767155149946e+01;
constexpr double d4_10 = -0.87139158377797299206789907490e+00;
constexpr double d4_11 = 0.22404374302607882758541771650e+01;
constexpr double d4_12 = 0.63157877876946881815570249290e+00;
constexpr double d4_13 = -0.88990336451333310820698117400e-01;
constexpr double d4_14 = 0.18148505520854727256656404962e+02;
constexpr double d4_15 = -0.91946323924783554000451984436e+01;
constexpr double d4_16 = -0.44360363875948939664310572000e+01;
constexpr double d5_1 = 0.10427508642579134603413151009e+02;
constexpr double d5_6 = 0.24228349177525818288430175319e+03;
constexpr double d5_7 = 0.16520045171727028198505394887e+03;
constexpr double d5_8 = -0.37454675472269020279518312152e+03;
constexpr double d5_9 = -0.22113666853125306036270938578e+02;
constexpr double d5_10 = 0.77334326684722638389603898808e+01;
constexpr double d5_11 = -0.30674084731089398182061213626e+02;
constexpr double d5_12 = -0.93321305264302278729567221706e+01;
constexpr double d5_13 = 0.15697238121770843886131091075e+02;
constexpr double d5_14 = -0.31139403219565177677282850411e+02;
constexpr double d5_15 = -0.93529243588444783865713862664e+01;
constexpr double d5_16 = 0.35816841486394083752465898540e+02;
constexpr double d6_1 = 0.19985053242002433820987653617e+02;
constexpr double d6_6 = -0.38703730874935176555105901742e+03;
constexpr double d6_7 = -0.18917813819516756882830838328e+03;
constexpr double d6_8 = 0.52780815920542364900561016686e+03;
constexpr double d6_9 = -0.11573902539959630126141871134e+02;
constexpr double d6_10 = 0.68812326946963000169666922661e+01;
constexpr double d6_11 = -0.10006050966910838403183860980e+01;
constexpr double d6_12 = 0.77771377980534432092869265740e+00;
constexpr double d6_13 = -0.27782057523535084065932004339e+01;
constexpr double d6_14 = -0.60196695231264120758267380846e+02;
constexpr double d6_15 = 0.84320405506677161018159903784e+02;
constexpr double d6_16 = 0.11992291136182789328035130030e+02;
constexpr double d7_1 = -0.25693933462703749003312586129e+02;
constexpr double d7_6 = -0.15418974869023643374053993627e+03;
constexpr double d7_7 = -0.23152937917604549567536039109e+03;
constexpr double d7_8 = 0.35763911791061412378285349910e+03;
constexpr double d7_9 = 0.93405324183624310003907691704e+02;
constexpr double d7_10 = -0.37458323136451633156875139351e+02;
constexpr double d7_11 = 0.10409964950896230045147246184e+03;
constexpr double d7_12 = 0.29840293426660503123344363579e+02;
constexpr double d7_13 = -0.43533456590011143754432175058e+02;
constexpr double d7_14 = 0.96324553959188282948394950600e+02;
constexpr double d7_15 = -0.39177261675615439165231486172e+02;
constexpr double d7_16 = -0.14972683625798562581422125276e+03;

// Hairer's step-control parameters: safety factor, bounds on h_new / h, error exponent.
constexpr double kSafety = 0.9;
constexpr double kMinFactor = 0.333;  // h_new >= 0.333 h
constexpr double kMaxFactor = 6.0;    // h_new <= 6 h
constexpr double kExponent = 1.0 / 8.0;
// A step within 1 % of the stop is stretched onto it (Hairer's code).
constexpr double kLandingStretch = 1.01;

}  // namespace

Dop853::Dop853(const StepControl& control) : control_(control) {
  step_control::validate_adaptive(name(), control_);
}

void Dop853::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(name(), system, t0, y0, t_end);
  system_ = &system;
  const Eigen::Index n = y0.size();
  for (Stages& stages : stages_) {
    for (VecX& k : stages) k.setZero(n);
  }
  for (VecX& k : dense_stages_) k.setZero(n);
  for (VecX& r : dense_terms_) r.setZero(n);
  dense_y_stage_.setZero(n);
  y_stage_.setZero(n);
  increment_.setZero(n);
  y_new_.setZero(n);
  error5_.setZero(n);
  error3_.setZero(n);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  h_max_ = control_.max_step > 0.0 ? control_.max_step : std::abs(t_end - t0);
  stats_ = IntegratorStats{};

  t_ = t_previous_ = t0;
  y_ = y0;
  y_previous_ = y0;
  accepted_ = 0;
  dense_ready_ = false;
  system_->derivative(t_, y_, stages_[accepted_][kStages - 1]);
  ++stats_.rhs_evaluations;
  step_control::absolute_tolerances(system, y0, control_.atol, atols_);
  h_ = control_.initial_step > 0.0 ? std::min(control_.initial_step, h_max_) : initial_step();
}

// Hairer's HINIT for order 8, with sk_i = atol_i + rtol |y0_i| and sums of squares:
//   h0 = 0.01 sqrt(sum (y0/sk)^2 / sum (f0/sk)^2)   (1e-6 if either sum is <= 1e-10),
//   one explicit Euler step of h0, f1 = f(t0 + h0, y0 + h0 f0),
//   d2 = sqrt(sum ((f1 - f0)/sk)^2) / h0,  d12 = max(d2, sqrt(sum (f0/sk)^2)),
//   h1 = (0.01 / d12)^(1/8)   (max(1e-6, 1e-3 h0) if d12 <= 1e-15),
//   h = min(100 h0, h1, h_max).
double Dop853::initial_step() {
  const VecX& f0 = stages_[accepted_][kStages - 1];
  VecX& f1 = trial_stages()[1];
  const double rtol = control_.rtol;
  double sum_f = 0.0;
  double sum_y = 0.0;
  for (Eigen::Index i = 0; i < y_.size(); ++i) {
    const double sk = atols_[i] + rtol * std::abs(y_[i]);
    sum_f += (f0[i] / sk) * (f0[i] / sk);
    sum_y += (y_[i] / sk) * (y_[i] / sk);
  }
  double h = (sum_f <= 1e-10 || sum_y <= 1e-10) ? 1e-6 : 0.01 * std::sqrt(sum_y / sum_f);
  if (!std::isfinite(h)) h = h_max_;  // a non-finite f0: the first step reports it
  h = std::min(h, h_max_);

  y_stage_ = y_ + (direction_ * h) * f0;
  system_->derivative(t_ + direction_ * h, y_stage_, f1);
  ++stats_.rhs_evaluations;
  double sum_df = 0.0;
  for (Eigen::Index i = 0; i < y_.size(); ++i) {
    const double sk = atols_[i] + rtol * std::abs(y_[i]);
    sum_df += ((f1[i] - f0[i]) / sk) * ((f1[i] - f0[i]) / sk);
  }
  const double d2 = std::sqrt(sum_df) / h;
  const double d12 = std::max(std::abs(d2), std::sqrt(sum_f));
  const double h1 = d12 <= 1e-15 ? std::max(1e-6, 1e-3 * h) : std::pow(0.01 / d12, kExponent);
  const double h_start = std::min({100.0 * h, h1, h_max_});
  return std::isfinite(h_start) ? h_start : h_max_;
}

// The stages, the tolerances taken from y0 at the start, and the lazy continuous extension's
// extra stages when the last step has made them (made again, they would count
// evaluations the uninterrupted run did not make).
void Dop853::archive_memory(StateArchive& archive) {
  archive_common(archive);
  archive_stage_sets(archive, direction_, h_max_, accepted_, stages_);
  archive_sized(archive, "atols", atols_);
  archive.flag("dense_ready", dense_ready_);
  for (std::size_t i = 0; i < dense_stages_.size(); ++i) {
    archive_sized(archive, fmt::format("k{}", i + 14), dense_stages_[i]);
  }
  for (std::size_t i = 0; i < dense_terms_.size(); ++i) {
    archive_sized(archive, fmt::format("r{}", i + 5), dense_terms_[i]);
  }
}

void Dop853::restart(double t, const VecX& y) {
  if (system_ == nullptr) throw std::logic_error("dop853: restart() before start()");
  if (y.size() != y_.size()) throw std::invalid_argument("dop853: restart() with a wrong-size y");
  t_ = t_previous_ = t;
  y_ = y;
  y_previous_ = y;
  dense_ready_ = false;
  system_->derivative(t_, y_, stages_[accepted_][kStages - 1]);
  ++stats_.rhs_evaluations;
}

StepOutcome Dop853::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("dop853: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);

  Stages& k = trial_stages();
  k[0] = accepted_stages()[kStages - 1];  // f at the current state
  const double h_min = step_control::minimum_step(t_);
  double h_abs = step_control::first_try(h_, h_max_, step_bound_, h_min);
  bool rejected_before = false;

  for (;;) {
    const step_control::ClippedStep clipped =
        step_control::clip_to_stop(t_, h_abs, t_stop, direction_, kLandingStretch);
    h_abs = clipped.h_abs;
    const double h = direction_ * h_abs;
    const double t_new = clipped.t_new;

    // Stages 2..12; k[i - 1] holds k_i.
    y_stage_ = y_ + (h * a2_1) * k[0];
    system_->derivative(t_ + c2 * h, y_stage_, k[1]);
    y_stage_ = y_ + h * (a3_1 * k[0] + a3_2 * k[1]);
    system_->derivative(t_ + c3 * h, y_stage_, k[2]);
    y_stage_ = y_ + h * (a4_1 * k[0] + a4_3 * k[2]);
    system_->derivative(t_ + c4 * h, y_stage_, k[3]);
    y_stage_ = y_ + h * (a5_1 * k[0] + a5_3 * k[2] + a5_4 * k[3]);
    system_->derivative(t_ + c5 * h, y_stage_, k[4]);
    y_stage_ = y_ + h * (a6_1 * k[0] + a6_4 * k[3] + a6_5 * k[4]);
    system_->derivative(t_ + c6 * h, y_stage_, k[5]);
    y_stage_ = y_ + h * (a7_1 * k[0] + a7_4 * k[3] + a7_5 * k[4] + a7_6 * k[5]);
    system_->derivative(t_ + c7 * h, y_stage_, k[6]);
    y_stage_ = y_ + h * (a8_1 * k[0] + a8_4 * k[3] + a8_5 * k[4] + a8_6 * k[5] + a8_7 * k[6]);
    system_->derivative(t_ + c8 * h, y_stage_, k[7]);
    y_stage_ = y_ + h * (a9_1 * k[0] + a9_4 * k[3] + a9_5 * k[4] + a9_6 * k[5] + a9_7 * k[6] +
                         a9_8 * k[7]);
    system_->derivative(t_ + c9 * h, y_stage_, k[8]);
    y_stage_ = y_ + h * (a10_1 * k[0] + a10_4 * k[3] + a10_5 * k[4] + a10_6 * k[5] + a10_7 * k[6] +
                         a10_8 * k[7] + a10_9 * k[8]);
    system_->derivative(t_ + c10 * h, y_stage_, k[9]);
    y_stage_ = y_ + h * (a11_1 * k[0] + a11_4 * k[3] + a11_5 * k[4] + a11_6 * k[5] + a11_7 * k[6] +
                         a11_8 * k[7] + a11_9 * k[8] + a11_10 * k[9]);
    system_->derivative(t_ + c11 * h, y_stage_, k[10]);
    y_stage_ = y_ + h * (a12_1 * k[0] + a12_4 * k[3] + a12_5 * k[4] + a12_6 * k[5] + a12_7 * k[6] +
                         a12_8 * k[7] + a12_9 * k[8] + a12_10 * k[9] + a12_11 * k[10]);
    system_->derivative(t_new, y_stage_, k[11]);
    stats_.rhs_evaluations += 11;

    increment_ = b1 * k[0] + b6 * k[5] + b7 * k[6] + b8 * k[7] + b9 * k[8] + b10 * k[9] +
                 b11 * k[10] + b12 * k[11];
    y_new_ = y_ + h * increment_;
    error5_ = er1 * k[0] + er6 * k[5] + er7 * k[6] + er8 * k[7] + er9 * k[8] + er10 * k[9] +
              er11 * k[10] + er12 * k[11];
    error3_ = increment_ - bhh1 * k[0] - bhh2 * k[8] - bhh3 * k[11];
    const double err =
        step_control::dop853_error(error5_, error3_, y_, y_new_, atols_, control_.rtol, h);
    if (!std::isfinite(err) || !y_new_.allFinite()) {
      ++stats_.rejected_steps;
      if (!step_control::shorten_after_blow_up(h_abs, h_min)) {
        h_ = h_abs;
        return StepOutcome::NonFiniteState;
      }
      rejected_before = true;
      continue;
    }

    // h_new = h / fac with fac = err^(1/8) / 0.9 kept in [1/6, 1/0.333].
    const double fac_err = std::pow(err, kExponent);
    if (err > 1.0) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      h_abs = std::max(h_min, h_abs / std::min(1.0 / kMinFactor, fac_err / kSafety));
      rejected_before = true;
      continue;
    }

    const double fac = std::clamp(fac_err / kSafety, 1.0 / kMaxFactor, 1.0 / kMinFactor);
    double h_next = h_abs / fac;
    if (rejected_before) h_next = std::min(h_next, h_abs);

    // Accepted: project, then k_13 = f at the projected state (the next step's k_1).
    y_previous_.swap(y_);
    y_.swap(y_new_);
    system_->project(t_new, y_);
    system_->derivative(t_new, y_, k[12]);
    ++stats_.rhs_evaluations;
    t_previous_ = t_;
    t_ = t_new;
    h_ = h_next;
    accepted_ = 1 - accepted_;
    dense_ready_ = false;
    ++stats_.accepted_steps;
    return StepOutcome::Ok;
  }
}

double Dop853::last_step_h_lambda() const {
  if (t_ == t_previous_) return 0.0;
  // y_stage_ still holds the last stage's argument: nothing writes it between a step's k_12
  // and the next step.
  // Each component in the error's own scale, sk_i = atol_i + rtol max(|y_i|, |y_new_i|), as
  // the step's error is measured: in the state's raw units a stiff spring's position and speed
  // differ by its frequency, and the Euclidean ratio would see k/m where the motion has sqrt(k/m).
  const Stages& k = accepted_stages();
  double slopes = 0.0, across = 0.0;
  for (Eigen::Index i = 0; i < y_.size(); ++i) {
    const double sk =
        atols_[i] + control_.rtol * std::max(std::abs(y_[i]), std::abs(y_previous_[i]));
    slopes += ((k[12][i] - k[11][i]) / sk) * ((k[12][i] - k[11][i]) / sk);
    across += ((y_[i] - y_stage_[i]) / sk) * ((y_[i] - y_stage_[i]) / sk);
  }
  if (!(across > 0.0)) return 0.0;
  return std::abs(t_ - t_previous_) * std::sqrt(slopes / across);
}

void Dop853::prepare_dense_output() const {
  const Stages& k = accepted_stages();
  const double h = t_ - t_previous_;
  const VecX& y0 = y_previous_;
  std::array<VecX, 3>& kd = dense_stages_;  // k_14, k_15, k_16

  dense_y_stage_ = y0 + h * (a14_1 * k[0] + a14_7 * k[6] + a14_8 * k[7] + a14_9 * k[8] +
                             a14_10 * k[9] + a14_11 * k[10] + a14_12 * k[11] + a14_13 * k[12]);
  system_->derivative(t_previous_ + c14 * h, dense_y_stage_, kd[0]);
  dense_y_stage_ = y0 + h * (a15_1 * k[0] + a15_6 * k[5] + a15_7 * k[6] + a15_8 * k[7] +
                             a15_11 * k[10] + a15_12 * k[11] + a15_13 * k[12] + a15_14 * kd[0]);
  system_->derivative(t_previous_ + c15 * h, dense_y_stage_, kd[1]);
  dense_y_stage_ = y0 + h * (a16_1 * k[0] + a16_6 * k[5] + a16_7 * k[6] + a16_8 * k[7] +
                             a16_9 * k[8] + a16_13 * k[12] + a16_14 * kd[0] + a16_15 * kd[1]);
  system_->derivative(t_previous_ + c16 * h, dense_y_stage_, kd[2]);
  stats_.rhs_evaluations += 3;

  dense_terms_[0] = h * (d4_1 * k[0] + d4_6 * k[5] + d4_7 * k[6] + d4_8 * k[7] + d4_9 * k[8] +
                         d4_10 * k[9] + d4_11 * k[10] + d4_12 * k[11] + d4_13 * k[12] +
                         d4_14 * kd[0] + d4_15 * kd[1] + d4_16 * kd[2]);
  dense_terms_[1] = h * (d5_1 * k[0] + d5_6 * k[5] + d5_7 * k[6] + d5_8 * k[7] + d5_9 * k[8] +
                         d5_10 * k[9] + d5_11 * k[10] + d5_12 * k[11] + d5_13 * k[12] +
                         d5_14 * kd[0] + d5_15 * kd[1] + d5_16 * kd[2]);
  dense_terms_[2] = h * (d6_1 * k[0] + d6_6 * k[5] + d6_7 * k[6] + d6_8 * k[7] + d6_9 * k[8] +
                         d6_10 * k[9] + d6_11 * k[10] + d6_12 * k[11] + d6_13 * k[12] +
                         d6_14 * kd[0] + d6_15 * kd[1] + d6_16 * kd[2]);
  dense_terms_[3] = h * (d7_1 * k[0] + d7_6 * k[5] + d7_7 * k[6] + d7_8 * k[7] + d7_9 * k[8] +
                         d7_10 * k[9] + d7_11 * k[10] + d7_12 * k[11] + d7_13 * k[12] +
                         d7_14 * kd[0] + d7_15 * kd[1] + d7_16 * kd[2]);
  dense_ready_ = true;
}

void Dop853::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  if (!dense_ready_) prepare_dense_output();
  // The nested form of the class comment expanded into weights of r2..r8, with r2..r4 written
  // out in y_n, y_{n+1}, k_1 and k_13.
  const double h = t_ - t_previous_;
  const double s = (t - t_previous_) / h;
  const double s1 = 1.0 - s;
  const double w2 = s;
  const double w3 = s * s1;
  const double w4 = w3 * s;
  const double w5 = w4 * s1;
  const double w6 = w5 * s;
  const double w7 = w6 * s1;
  const double w8 = w7 * s;
  const double w_delta = w2 - w3 + 2.0 * w4;
  const Stages& k = accepted_stages();
  y_out = (1.0 - w_delta) * y_previous_ + w_delta * y_ + (h * (w3 - w4)) * k[0] - (h * w4) * k[12] +
          w5 * dense_terms_[0] + w6 * dense_terms_[1] + w7 * dense_terms_[2] + w8 * dense_terms_[3];
}

}  // namespace tumble

#include "report/tables.hpp"

#include "analysis/stats.hpp"
#include "report/csv_table.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

using sweep::csv_field;

namespace {

std::vector<std::string> param_cells(const Analysis& a, const GridPoint& p) {
  std::vector<std::string> cells;
  for (const auto& ptr : a.params) cells.push_back(sweep::csv_cell(leaf(p, ptr)));
  return cells;
}

std::vector<std::string> mean_sem_cells(std::span<const double> xs) {
  const auto m = analysis::mean_sem(xs);
  return {sweep::csv_number(m.mean), sweep::csv_number(m.sem)};
}

// The run quantities averaged in curves.csv, with their accessors.
const std::vector<std::pair<std::string, double RunData::*>>& curve_quantities() {
  static const std::vector<std::pair<std::string, double RunData::*>> q = {
      {"D", &RunData::D},
      {"D_avg", &RunData::D_avg},
      {"U_b_hat", &RunData::U_b_hat},
      {"K", &RunData::K},
      {"N", &RunData::N},
      {"l_reached", &RunData::l_reached},
      {"wall_s", &RunData::wall_s},
      {"D_chord", &RunData::D_chord},
      {"D_kappa", &RunData::D_kappa}};
  return q;
}

}  // namespace

std::string runs_csv(const Analysis& a) {
  Table t(cat(
      std::vector<std::string>{"file", "point"}, a.param_names,
      std::vector<std::string>{"seed", "status", "reason", "D_l_min", "D_l_max", "D", "D_avg",
                               "l_reached", "wall_s", "U_b_hat", "K", "N", "D_chord", "D_kappa"}));
  for (const auto& r : a.runs) {
    std::vector<std::string> params(a.params.size());
    if (r.point >= 0) params = param_cells(a, a.points[r.point]);
    t.add(cat(
        std::vector<std::string>{csv_field(r.file), r.point >= 0 ? std::to_string(r.point) : ""},
        params,
        std::vector<std::string>{
            sweep::csv_cell(r.seed), r.status, csv_field(r.reason),
            sweep::csv_number(a.settings.D_window.l_min),
            sweep::csv_number(a.settings.D_window.l_max), sweep::csv_number(r.D),
            sweep::csv_number(r.D_avg), sweep::csv_number(r.l_reached), sweep::csv_number(r.wall_s),
            sweep::csv_number(r.U_b_hat), sweep::csv_number(r.K), sweep::csv_number(r.N),
            sweep::csv_number(r.D_chord), sweep::csv_number(r.D_kappa)}));
  }
  return t.text();
}

std::string curves_csv(const Analysis& a) {
  std::vector<std::string> header = {"point"};
  header.insert(header.end(), a.param_names.begin(), a.param_names.end());
  for (const char* h : {"n", "n_failed", "n_missing", "D_l_min", "D_l_max"}) header.push_back(h);
  for (const auto& [name, field] : curve_quantities()) {
    header.push_back(name + "_mean");
    header.push_back(name + "_sem");
  }
  Table t(header);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const GridPoint& p = a.points[i];
    std::vector<std::string> row =
        cat(std::vector<std::string>{std::to_string(i)}, param_cells(a, p));
    for (const std::size_t n : {p.complete.size(), p.failed, p.missing})
      row.push_back(std::to_string(n));
    row.push_back(sweep::csv_number(a.settings.D_window.l_min));
    row.push_back(sweep::csv_number(a.settings.D_window.l_max));
    for (const auto& [name, field] : curve_quantities())
      for (auto& c : mean_sem_cells(values(p, field))) row.push_back(std::move(c));
    t.add(row);
  }
  return t.text();
}

std::string view_csv(const Analysis& a, const View& v) {
  std::vector<std::string> header;
  for (const auto& o : v.others) header.push_back(column_name(o));
  header.push_back(v.name);
  for (const char* h : {"n", "D_mean", "D_sem", "D_l_min", "D_l_max", "D_chord_mean", "D_chord_sem",
                        "D_kappa_mean", "D_kappa_sem", "D_sd", "D_chord_sd", "D_kappa_sd",
                        "D_distinct", "D_chord_distinct", "D_kappa_distinct"})
    header.push_back(h);
  Table t(header);
  for (const std::size_t i : v.order) {
    const GridPoint& p = a.points[i];
    std::vector<std::string> row;
    for (const auto& o : v.others) row.push_back(sweep::csv_cell(leaf(p, o)));
    row.push_back(sweep::csv_cell(leaf(p, v.pointer)));
    row.push_back(std::to_string(p.complete.size()));
    for (auto& c : mean_sem_cells(values(p, &RunData::D))) row.push_back(std::move(c));
    row.push_back(sweep::csv_number(a.settings.D_window.l_min));
    row.push_back(sweep::csv_number(a.settings.D_window.l_max));
    for (const auto field : {&RunData::D_chord, &RunData::D_kappa})
      for (auto& c : mean_sem_cells(values(p, field))) row.push_back(std::move(c));
    // Decorrelation of the seeds: the spread (SD) and the distinct outcomes (values more than
    // 0.01 apart) of each variant; ten seeds of one trajectory give SD ~ 0 and one outcome.
    const auto variants = {&RunData::D, &RunData::D_chord, &RunData::D_kappa};
    for (const auto field : variants)
      row.push_back(sweep::csv_number(analysis::mean_sem(values(p, field)).sd));
    for (const auto field : variants)
      row.push_back(std::to_string(analysis::distinct_outcomes(values(p, field))));
    t.add(row);
  }
  return t.text();
}

std::string exponents_csv(const Analysis& a, const Fits& fits) {
  Table t(cat(
      std::vector<std::string>{"point"}, a.param_names,
      std::vector<std::string>{"name", "series", "value", "stderr", "stderr_ols",
                               "stderr_bootstrap", "log_prefactor", "window_l_min", "window_l_max",
                               "fit_l_min", "fit_l_max", "n_points", "n_seeds", "method", "ok"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (std::size_t k = 0; k < exponent_specs().size(); ++k) {
      const auto& spec = exponent_specs()[k];
      const ExponentFit& f = fits[i][k];
      const LWindow& w = a.settings.fit_windows.at(spec.name);
      const bool boot = use_bootstrap(f);
      t.add(cat(std::vector<std::string>{std::to_string(i)}, param_cells(a, a.points[i]),
                std::vector<std::string>{
                    spec.name, spec.series, sweep::csv_number(f.fit.exponent),
                    sweep::csv_number(reported_stderr(f)), sweep::csv_number(f.fit.stderr_),
                    sweep::csv_number(f.stderr_bootstrap), sweep::csv_number(f.fit.log_prefactor),
                    sweep::csv_number(w.l_min), sweep::csv_number(w.l_max),
                    sweep::csv_number(f.fit.l_min), sweep::csv_number(f.fit.l_max),
                    std::to_string(f.fit.n_points), std::to_string(f.seeds),
                    std::string(f.auto_window ? "auto-log" : "ols") + (boot ? "+bootstrap" : ""),
                    f.fit.ok ? "true" : "false"}));
    }
  }
  return t.text();
}

std::string series_csv(const Analysis& a, const std::vector<MeanSeries>& ms) {
  std::vector<std::string> header =
      cat(std::vector<std::string>{"point"}, a.param_names, std::vector<std::string>{"l", "n"});
  const auto names = cat(a.kept, predicted_series());
  for (const auto& name : names) {
    header.push_back(name + "_mean");
    header.push_back(name + "_sem");
  }
  Table t(header);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto params = param_cells(a, a.points[i]);
    const MeanSeries& m = ms[i];
    for (std::size_t j = 0; j < m.l.size(); ++j) {
      std::vector<std::string> row =
          cat(std::vector<std::string>{std::to_string(i)}, params,
              std::vector<std::string>{sweep::csv_number(m.l[j]), std::to_string(m.n[j])});
      for (const auto& name : names) {
        row.push_back(sweep::csv_number(m.q.at(name)[j].mean));
        row.push_back(sweep::csv_number(m.q.at(name)[j].sem));
      }
      t.add(row);
    }
  }
  return t.text();
}

std::string distributions_csv(const Analysis& a, const std::vector<Samples>& samples,
                              const Distributions& ds) {
  Table t(cat(std::vector<std::string>{"point"}, a.param_names,
              std::vector<std::string>{"quantity", "l", "n_runs", "n", "mu", "mu_stderr", "sigma",
                                       "sigma_stderr", "ok", "bin", "ln_lo", "ln_hi", "count",
                                       "density", "fit_density", "mu_ls", "sigma_ls", "ls_ok"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto params = param_cells(a, a.points[i]);
    for (const Distribution& d : ds[i]) {
      const std::vector<std::string> fit = {d.quantity,
                                            sweep::csv_number(a.distribution_l),
                                            std::to_string(samples[i].runs),
                                            std::to_string(d.fit.n),
                                            sweep::csv_number(d.fit.mu),
                                            sweep::csv_number(d.fit.mu_stderr),
                                            sweep::csv_number(d.fit.sigma),
                                            sweep::csv_number(d.fit.sigma_stderr),
                                            d.fit.ok ? "true" : "false"};
      const auto head = cat(std::vector<std::string>{std::to_string(i)}, params, fit);
      const std::vector<std::string> ls = {sweep::csv_number(d.ls_fit.mu),
                                           sweep::csv_number(d.ls_fit.sigma),
                                           d.ls_fit.ok ? "true" : "false"};
      if (d.hist.lo.empty()) {
        t.add(cat(head, std::vector<std::string>{"", "nan", "nan", "0", "nan", "nan"}, ls));
        continue;
      }
      for (std::size_t b = 0; b < d.hist.lo.size(); ++b)
        t.add(cat(head,
                  std::vector<std::string>{
                      std::to_string(b), sweep::csv_number(d.hist.lo[b]),
                      sweep::csv_number(d.hist.hi[b]), std::to_string(d.hist.count[b]),
                      sweep::csv_number(d.hist.density[b]), sweep::csv_number(d.fit_density[b])},
                  ls));
    }
  }
  return t.text();
}

std::string loop_sensitivity_csv(const Analysis& a, const std::vector<Samples>& samples) {
  Table t(cat(std::vector<std::string>{"point"}, a.param_names,
              std::vector<std::string>{"l", "n_runs", "smoothing_r", "min_prominence", "loops",
                                       "mu", "mu_stderr", "sigma", "sigma_stderr", "ok"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (const auto& row : samples[i].loop_sensitivity)
      t.add(cat(std::vector<std::string>{std::to_string(i)}, param_cells(a, a.points[i]),
                std::vector<std::string>{
                    sweep::csv_number(a.distribution_l), std::to_string(samples[i].runs),
                    sweep::csv_number(row.smoothing_r), sweep::csv_number(row.min_prominence),
                    std::to_string(row.loops), sweep::csv_number(row.fit.mu),
                    sweep::csv_number(row.fit.mu_stderr), sweep::csv_number(row.fit.sigma),
                    sweep::csv_number(row.fit.sigma_stderr), row.fit.ok ? "true" : "false"}));
  }
  return t.text();
}

std::string morphology_csv(const Analysis& a, const std::vector<Samples>& samples) {
  Table t(cat(std::vector<std::string>{"file", "point"}, a.param_names,
              std::vector<std::string>{"seed", "l", "D", "D_chord", "D_kappa", "chord_R",
                                       "reversals", "order_length_R", "min_block_R"}));
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (const auto& o : samples[i].orders)
      t.add(cat(std::vector<std::string>{csv_field(o.run->file), std::to_string(i)},
                param_cells(a, a.points[i]),
                std::vector<std::string>{
                    sweep::csv_cell(o.run->seed), sweep::csv_number(o.l),
                    sweep::csv_number(o.order.D), sweep::csv_number(o.order.D_chord),
                    sweep::csv_number(o.order.D_kappa), sweep::csv_number(o.order.chord_length_R),
                    std::to_string(o.order.reversals), sweep::csv_number(o.order.order_length_R),
                    sweep::csv_number(sweep::kMinSenseBlock_R)}));
  return t.text();
}

}  // namespace wirepack::report

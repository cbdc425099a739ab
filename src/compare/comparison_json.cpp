#include "src/compare/comparison_json.hpp"

#include "src/io/json_number.hpp"

namespace rollspec::compare {

namespace {

using json = nlohmann::ordered_json;

// A spectrum as drawn (python-post's report plots it): the measurement through the model's estimator, or
// the PSD table as read; null without one.
json spectrum_json(const MeasuredSpectrum* m) {
  if (!m) return nullptr;
  return {{"frequency_hz", m->frequency}, {"psd", m->psd}, {"units", "(m/s^2)^2/Hz"}, {"model_bins", m->model_grid}};
}

}  // namespace

json comparison_json(const Comparison& c) {
  const io::BandLevels& b = c.bands;
  const MeasuredSpectrum& m = c.measurement;
  const Verdict& v = c.verdict;
  const bool records = m.records > 0.0;  // M known (the prediction intervals also need has_interval)
  json bands = json::array();
  for (const auto& r : v.rows)
    bands.push_back({{"centre_hz", r.centre},
                     {"lower_hz", b.lower[r.band]},
                     {"upper_hz", b.upper[r.band]},
                     {"simulated_db", io::json_number(r.simulated)},
                     {"measured_db", io::json_number(r.measured)},
                     {"delta_db", io::json_number(r.delta)},
                     {"ci_lower_db", io::json_number(r.ci_lower)},
                     {"ci_upper_db", io::json_number(r.ci_upper)},
                     {"prediction_lower_db", io::json_number(r.pred_lower)},
                     {"prediction_upper_db", io::json_number(r.pred_upper)},
                     {"noise_db", io::json_number(r.noise)},
                     {"use", band_use_name(r.use)},
                     {"inside", c.has_interval ? json(records ? r.inside_prediction : r.inside_ci) : json(nullptr)}});
  const auto& t = v.test.result;
  json offset = nullptr;
  if (v.offset)
    offset = {{"estimate_db", v.offset->estimate},
              {"lower_db", v.offset->lower},
              {"upper_db", v.offset->upper},
              {"dof", v.offset->dof},
              {"bands", v.tested},
              {"method", "weighted least squares, each band by its own variance (kernels/spectral D-34)"}};
  json references = json::array();
  for (const auto& ref : c.references)
    references.push_back({{"id", ref.id}, {"citation", ref.citation}, {"doi", ref.doi}});
  return {
      {"result", c.result},
      {"sensor", b.sensor},
      {"measurement", m.source},
      {"column", c.column.empty() ? json(nullptr) : json(c.column)},
      {"realisations", b.realisations},
      {"confidence_level", b.confidence},
      {"interval_method", b.interval_method},
      {"measured_averages", records ? json(m.records) : json(nullptr)},
      {"measured_averages_source", m.records_source},
      {"measurement_notes", m.notes},
      {"table_term",
       {{"factor", v.table_factor},
        {"table", b.table.empty() ? json(nullptr) : json(b.table)},
        {"units", b.table_units},
        {"dof", io::json_number(b.table_dof)},
        {"estimated", b.table_units >= 2}}},
      {"loss_of_contact_share", io::json_number(c.loss.share)},
      {"loss_of_contact_warning", c.loss.warning.empty() ? json(nullptr) : json(c.loss.warning)},
      {"loss_of_contact_note", c.loss.note.empty() ? json(nullptr) : json(c.loss.note)},
      {"question", v.question},
      {"bands", bands},
      {"rms_db_error", io::json_number(v.rms_db)},
      {"inside", c.has_interval ? v.inside : 0},
      {"judged", v.judged},
      {"bands_compared", v.rows.size()},
      {"bands_tested", v.tested},
      {"level_offset", offset},
      {"warnings", v.warnings},
      {"p_value", t.defined ? json(t.p_value) : json(nullptr)},
      {"combined_test",
       {{"method", t.draws > 0 ? "Hotelling T2, law by parametric bootstrap with the table term (kernels/spectral D-31)"
                               : "Hotelling T2, F law (kernels/spectral D-26)"},
        {"level", v.test.level},
        {"defined", t.defined},
        {"rejected", t.defined ? json(v.test.rejected) : json(nullptr)},
        {"t2", t.defined ? json(t.t2) : json(nullptr)},
        {"f", t.defined && t.draws == 0 ? json(t.f) : json(nullptr)},
        {"dof", t.defined && t.draws == 0 ? json::array({t.dof1, t.dof2}) : json(nullptr)},
        {"bootstrap_draws", t.draws},
        {"bands", v.test.bands},
        {"verdict", v.test.verdict}}},
      {"measured_psd", spectrum_json(&m)},
      {"noise_psd", spectrum_json(c.noise ? &*c.noise : nullptr)},
      {"references", references}};
}

}  // namespace rollspec::compare

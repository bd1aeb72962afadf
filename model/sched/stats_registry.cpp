#include "model/sched/stats_registry.h"

#include <stdexcept>

namespace rtsim {

void StatsRegistry::counter(const std::string& name, uint64_t value) {
  if (has(name)) throw std::logic_error("stat " + name + " reported twice");
  values_.emplace_back(name, double(value));
  integral_.push_back(true);
}

void StatsRegistry::real(const std::string& name, double value) {
  if (has(name)) throw std::logic_error("stat " + name + " reported twice");
  values_.emplace_back(name, value);
  integral_.push_back(false);
}

void StatsRegistry::ratio(const std::string& name, const std::string& numerator,
                          const std::string& denominator, double scale) {
  ratios_.push_back({name, numerator, denominator, scale});
}

const std::pair<std::string, double>* StatsRegistry::find(const std::string& name) const {
  for (const auto& v : values_)
    if (v.first == name) return &v;
  return nullptr;
}

bool StatsRegistry::has(const std::string& name) const {
  if (find(name)) return true;
  for (const Ratio& r : ratios_)
    if (r.name == name) return true;
  return false;
}

double StatsRegistry::value(const std::string& name) const {
  if (const auto* v = find(name)) return v->second;
  for (const Ratio& r : ratios_) {
    if (r.name != name) continue;
    double den = value(r.denominator);
    return den == 0 ? 0.0 : value(r.numerator) / den * r.scale;
  }
  return 0.0;
}

nlohmann::ordered_json StatsRegistry::to_json() const {
  nlohmann::ordered_json counters = nlohmann::ordered_json::object();
  for (size_t i = 0; i < values_.size(); ++i) {
    if (integral_[i])
      counters[values_[i].first] = uint64_t(values_[i].second);
    else
      counters[values_[i].first] = values_[i].second;
  }
  nlohmann::ordered_json derived = nlohmann::ordered_json::object();
  for (const Ratio& r : ratios_) derived[r.name] = value(r.name);
  return {{"counters", counters}, {"derived", derived}};
}

}  // namespace rtsim

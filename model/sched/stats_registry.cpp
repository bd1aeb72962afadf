#include "model/sched/stats_registry.h"

#include <stdexcept>

namespace rtsim {

void StatsRegistry::add(const std::string& name, double value, Kind kind) {
  if (has(name)) throw std::logic_error("stat " + name + " reported twice");
  index_.emplace(name, values_.size());
  values_.emplace_back(name, value);
  kinds_.push_back(kind);
}

void StatsRegistry::counter(const std::string& name, uint64_t value) {
  add(name, double(value), Kind::Counter);
}

void StatsRegistry::real(const std::string& name, double value) {
  add(name, value, Kind::Real);
}

void StatsRegistry::gauge(const std::string& name, uint64_t value) {
  add(name, double(value), Kind::Gauge);
}

void StatsRegistry::subtract(const StatsRegistry& before) {
  for (size_t i = 0; i < values_.size(); ++i) {
    if (kinds_[i] == Kind::Gauge) continue;
    // Snapshots list their stats in the same order; look a name up only where they part.
    const auto& [name, value] = values_[i];
    const std::pair<std::string, double>* old =
        i < before.values_.size() && before.values_[i].first == name ? &before.values_[i]
                                                                     : before.find(name);
    if (old) values_[i].second = value - old->second;
  }
}

void StatsRegistry::ratio(const std::string& name, const std::string& numerator,
                          const std::string& denominator, double scale) {
  ratios_.push_back({name, numerator, denominator, scale});
}

const std::pair<std::string, double>* StatsRegistry::find(const std::string& name) const {
  auto it = index_.find(name);
  return it == index_.end() ? nullptr : &values_[it->second];
}

bool StatsRegistry::has(const std::string& name) const {
  if (find(name)) return true;
  for (const Ratio& r : ratios_)
    if (r.name == name) return true;
  return false;
}

double StatsRegistry::units_sum(uint32_t units, const std::string& suffix) const {
  double total = 0;
  for (uint32_t i = 0; i < units; ++i) total += value("rt" + std::to_string(i) + suffix);
  return total;
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
    if (kinds_[i] != Kind::Real)
      counters[values_[i].first] = uint64_t(values_[i].second);
    else
      counters[values_[i].first] = values_[i].second;
  }
  nlohmann::ordered_json derived = nlohmann::ordered_json::object();
  for (const Ratio& r : ratios_) derived[r.name] = value(r.name);
  return {{"counters", counters}, {"derived", derived}};
}

std::vector<std::string> StatsRegistry::names() const {
  std::vector<std::string> all;
  for (const auto& [name, value] : values_) all.push_back(name);
  for (const Ratio& ratio : ratios_) all.push_back(ratio.name);
  return all;
}

}  // namespace rtsim

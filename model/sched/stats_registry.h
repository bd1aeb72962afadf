// The statistics of one run under dotted per-instance names ("mem.l1.rt0.hits"): plain counters
// that the modules report at the end, and derived statistics declared once as formulas
// (numerator / denominator * scale) that are computed only when written, as in gem5.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace rtsim {

class StatsRegistry {
 public:
  // A counter (integer) or an accumulated quantity (real, e.g. fractional busy cycles).
  void counter(const std::string& name, uint64_t value);
  void real(const std::string& name, double value);
  // A level, not an accumulation (a maximum, say): written as an integer, kept by subtract().
  void gauge(const std::string& name, uint64_t value);
  // name = numerator / denominator * scale, computed when written (0 if the denominator is 0).
  void ratio(const std::string& name, const std::string& numerator, const std::string& denominator,
             double scale = 1.0);

  // Counters and reals become what accrued since `before` (a snapshot of the same run taken
  // earlier: ChampSim's snapshot-and-subtract); names absent from it count from 0.
  void subtract(const StatsRegistry& before);

  bool has(const std::string& name) const;
  double value(const std::string& name) const;  // a counter, a real or a ratio; 0 if absent
  // The sum over RT units 0 .. units - 1 of "rtI" + suffix (suffix: ".box.tests", say).
  double units_sum(uint32_t units, const std::string& suffix) const;
  // Every name: counters, reals and gauges, then ratios, each in the order added.
  std::vector<std::string> names() const;
  // {"counters": {...}, "derived": {...}}, each in the order added.
  nlohmann::ordered_json to_json() const;

 private:
  struct Ratio {
    std::string name, numerator, denominator;
    double scale;
  };
  const std::pair<std::string, double>* find(const std::string& name) const;
  std::vector<std::pair<std::string, double>> values_;
  std::unordered_map<std::string, size_t> index_;  // of values_, by name
  enum class Kind : uint8_t { Counter, Real, Gauge };
  void add(const std::string& name, double value, Kind kind);
  std::vector<Kind> kinds_;
  std::vector<Ratio> ratios_;
};

}  // namespace rtsim

#include "reports/validate/sim_runs.h"

#include <stdexcept>

#include "model/sc/fork_run.h"
#include "model/sc/rt_simulator.h"

namespace rtsim::validation {

double SimFigures::operator[](const std::string& name) const {
  for (const char* part : {"counters", "derived"}) {
    auto it = doc_[part].find(name);
    if (it != doc_[part].end()) return it->get<double>();
  }
  throw std::logic_error("rtsim validate: a run has no stat " + name);
}

bool SimFigures::has(const std::string& name) const {
  return doc_["counters"].contains(name) || doc_["derived"].contains(name);
}

uint32_t SimFigures::units() const {
  uint32_t units = 0;
  while (has("rt" + std::to_string(units) + ".rays")) ++units;
  return units;
}

double SimFigures::units_sum(const std::string& name) const {
  double sum = 0;
  for (uint32_t unit = 0, n = units(); unit < n; ++unit)
    sum += (*this)["rt" + std::to_string(unit) + "." + name];
  return sum;
}

std::vector<SimFigures> simulate(const Target& target, const std::vector<SimJob>& jobs) {
  for (const SimJob& job : jobs) {
    std::string problem = hw_config_problem(target.as_run(job.config));
    if (!problem.empty())  // a machine the check built, not the user's config: a bug of the check
      throw std::logic_error("rtsim validate: a check built an impossible machine: " + problem);
  }
  std::vector<std::function<std::string()>> work;
  for (const SimJob& job : jobs)
    work.push_back([&job, &target] {
      VectorRaySource source(*job.rays);
      RtSimulator sim(target.as_run(job.config), *job.image, source);
      sim.run();
      StatsRegistry stats;
      sim.report(stats);
      nlohmann::json doc = stats.to_json();
      uint64_t count = 0, sum = 0;
      for (const RayTypeStats& type : sim.collected().by_type()) {
        count += type.latency.count();
        sum += type.latency.sum();
      }
      doc["latency_mean"] = count ? double(sum) / double(count) : 0.0;
      return doc.dump();
    });
  std::vector<SimFigures> out;
  for (const std::string& text : run_in_children(work, 2))
    out.emplace_back(nlohmann::json::parse(text));
  return out;
}

HwConfig unloaded(const HwConfig& config) {
  HwConfig c = config;
  for (MemoryLevelConfig& level : c.memory) {
    level.cache.bank_ports = 0;
    level.cache.bytes_per_cycle = 0;
    level.link.bytes_per_cycle = 0;
  }
  c.sim.quantum_cycles = 1;
  c.sort.key = SortKey::None;
  c.rt.mode = TraversalMode::DepthFirst;
  c.rt.prefetch = PrefetchConfig{};
  c.banked_dram.refresh = DramRefresh::None;
  return c;
}

}  // namespace rtsim::validation

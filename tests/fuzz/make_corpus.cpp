// Writes a few valid ray streams as the fuzzer's starting corpus (into the folder argv[1]).
#include <string>

#include "traces/stream.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  for (uint32_t n : {0u, 1u, 5u, 40u}) {
    rtsim::StreamHeader header;
    header.scene_source = "builtin:cornell";
    header.workload = "fuzz";
    header.chunk_rays = 16;
    rtsim::RayStreamWriter writer(std::string(argv[1]) + "/seed" + std::to_string(n) + ".rays",
                                  header);
    for (uint32_t i = 0; i < n; ++i) {
      rtsim::Ray ray;
      ray.org = {float(i), 1.0f, -2.0f};
      ray.dir = {0.0f, -0.0f, 1.0f};
      ray.type = static_cast<rtsim::RayType>(i % rtsim::kRayTypeCount);
      ray.pixel = i;
      writer.write(ray);
    }
    writer.finish();
  }
  return 0;
}

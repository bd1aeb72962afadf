// Energy of one ray-box and one ray-triangle test (issue 20): the arithmetic a test does, by
// AQB8's operation counts (ISCA 2025; its repository's computations.md), at Horowitz's 45 nm
// energies per operation (ISSCC 2014), scaled to the node as logic (logic_energy_scale). The
// datapath only: pipeline registers, operand delivery and control are left out (SOURCES.md, C).
#pragma once

#include "model/energy/process_node.h"

namespace rtsim {

struct ArithmeticOps {
  double fp32_mul = 0, fp32_add = 0;  // multiplies; adds and subtracts
  double int8_mul = 0, int32_add = 0;
  double compares = 0;  // charged as 32-bit integer adds (Horowitz lists no compare)
};

ArithmeticOps fp32_box_test();       // one box: 6 multiplies, 6 adds, 7 compares
ArithmeticOps quantized_box_test();  // an 8-bit quantized box: the same in int8 and int32
ArithmeticOps triangle_test();       // Möller-Trumbore with its depth test and hit finalise
ArithmeticOps transform_test();      // an instance's 3x4 transform of a ray's origin and direction

double arithmetic_pj(const ArithmeticOps& ops, const ProcessNode& node);
// mm² of a pipelined datapath doing ops once a cycle: the operators' areas at 45 nm (Horowitz,
// ISSCC 2014) and 30% for pipeline registers (an assumption), scaled to the node.
double arithmetic_area_mm2(const ArithmeticOps& ops, const ProcessNode& node);

}  // namespace rtsim

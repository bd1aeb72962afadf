#include "model/energy/test_units.h"

namespace rtsim {
namespace {

// pJ per operation at 45 nm, 0.9 V (Horowitz, ISSCC 2014, Fig. 1.1.9).
constexpr double kFp32Mul = 3.7, kFp32Add = 0.9, kInt8Mul = 0.2, kInt32Add = 0.1;

}  // namespace

ArithmeticOps fp32_box_test() {
  ArithmeticOps ops;
  ops.fp32_mul = 6;
  ops.fp32_add = 6;
  ops.compares = 7;
  return ops;
}

ArithmeticOps quantized_box_test() {
  ArithmeticOps ops;
  ops.int8_mul = 6;
  ops.int32_add = 6;
  ops.compares = 7;
  return ops;
}

ArithmeticOps triangle_test() {
  ArithmeticOps ops;
  ops.fp32_mul = 21 + 5 + 3;  // edges, determinant and barycentrics; depth; hit
  ops.fp32_add = 16 + 2;
  ops.compares = 1 + 2;
  return ops;
}

double arithmetic_pj(const ArithmeticOps& ops, const ProcessNode& node) {
  double at_45nm = ops.fp32_mul * kFp32Mul + ops.fp32_add * kFp32Add + ops.int8_mul * kInt8Mul +
                   (ops.int32_add + ops.compares) * kInt32Add;
  return at_45nm * logic_energy_scale(node);
}

}  // namespace rtsim

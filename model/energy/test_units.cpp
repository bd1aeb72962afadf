#include "model/energy/test_units.h"

namespace rtsim {
namespace {

// pJ per operation at 45 nm, 0.9 V (Horowitz, ISSCC 2014, Fig. 1.1.9).
constexpr double kFp32Mul = 3.7, kFp32Add = 0.9, kInt8Mul = 0.2, kInt32Add = 0.1;

}  // namespace

// {fp32 multiplies, fp32 adds, int8 multiplies, int32 adds, compares}
ArithmeticOps fp32_box_test() {
  return {6, 6, 0, 0, 7};
}

ArithmeticOps quantized_box_test() {
  return {0, 0, 6, 6, 7};
}

ArithmeticOps triangle_test() {
  return {21 + 5 + 3, 16 + 2, 0, 0, 1 + 2};  // edges and barycentrics; depth test; hit
}

double arithmetic_pj(const ArithmeticOps& ops, const ProcessNode& node) {
  double at_45nm = ops.fp32_mul * kFp32Mul + ops.fp32_add * kFp32Add + ops.int8_mul * kInt8Mul +
                   (ops.int32_add + ops.compares) * kInt32Add;
  return at_45nm * logic_energy_scale(node);
}

}  // namespace rtsim

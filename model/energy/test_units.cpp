#include "model/energy/test_units.h"

namespace rtsim {
namespace {

// pJ per operation at 45 nm, 0.9 V (Horowitz, ISSCC 2014, Fig. 1.1.9).
constexpr double kFp32Mul = 3.7, kFp32Add = 0.9, kInt8Mul = 0.2, kInt32Add = 0.1;
// µm² per operator at 45 nm (the same figure; recalled, SOURCES.md C.2).
constexpr double kFp32MulArea = 7700, kFp32AddArea = 4184, kInt8MulArea = 282, kInt32AddArea = 137;
constexpr double kPipelineRegisters = 1.3;

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

ArithmeticOps transform_test() {
  return {9 + 9, 9 + 6, 0, 0, 0};  // origin: 9 multiplies, 9 adds; direction: 9 and 6
}

double arithmetic_pj(const ArithmeticOps& ops, const ProcessNode& node) {
  double at_45nm = ops.fp32_mul * kFp32Mul + ops.fp32_add * kFp32Add + ops.int8_mul * kInt8Mul +
                   (ops.int32_add + ops.compares) * kInt32Add;
  return at_45nm * logic_energy_scale(node);
}

double arithmetic_area_mm2(const ArithmeticOps& ops, const ProcessNode& node) {
  double um2 = ops.fp32_mul * kFp32MulArea + ops.fp32_add * kFp32AddArea +
               ops.int8_mul * kInt8MulArea + (ops.int32_add + ops.compares) * kInt32AddArea;
  return um2 * kPipelineRegisters * node.area_scale * 1e-6;
}

}  // namespace rtsim

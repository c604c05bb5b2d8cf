#pragma once
// `rcache verify` and `rcache devices` (ARCHITECTURE.md §Kernels).
#include <ostream>
#include <string>

namespace rc {

// Runs every kernel family on the device named by deviceSpec ("opencl", "opencl:P:D", "auto",
// "" = RC_DEVICE/auto; "cpu" checks the scalar backend against the references) against the
// scalar references on seeded random and edge-case inputs at `order` (0 = each of 1, 2, 5, 10, 16).
// Prints one row per family and order: family, order, max abs error, max rel error, tolerance
// (at the worst element), err/tol, PASS/FAIL. Returns 0 only if every row passes.
int runVerify(const std::string& deviceSpec, int order, std::ostream& out);

// One line per OpenCL platform/device (index, name, type, compute units, memory), or a line
// saying that there is none.
void listDevices(std::ostream& out);

}  // namespace rc

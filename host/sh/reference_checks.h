#pragma once
// Batch validation shared by the scalar references (host/sh/reference_*.cpp): every malformed
// batch becomes one rc::Error naming the function, the array and both sizes.
#include <cstddef>
#include <string>

#include "core/error.h"
#include "sh/batches.h"

namespace rc::ref::detail {

inline void checkOrder(const char* fn, int order) {
  if (order < 1 || order > kMaxReferenceOrder)
    throw Error(std::string("ref::") + fn + ": order " + std::to_string(order) + " outside 1.." +
                std::to_string(kMaxReferenceOrder));
}

inline void checkCount(const char* fn, const char* what, long long value) {
  if (value < 0) throw Error(std::string("ref::") + fn + ": " + what + " = " + std::to_string(value) + " is negative");
}

inline void checkSize(const char* fn, const char* array, size_t actual, long long expected) {
  if (static_cast<long long>(actual) != expected)
    throw Error(std::string("ref::") + fn + ": " + array + " has " + std::to_string(actual) + " values, expected " +
                std::to_string(expected));
}

inline void checkRange(const char* fn, int begin, int end, int count) {
  if (begin < 0 || end > count || begin > end)
    throw Error(std::string("ref::") + fn + ": range [" + std::to_string(begin) + ", " + std::to_string(end) +
                ") outside [0, " + std::to_string(count) + ")");
}

}  // namespace rc::ref::detail

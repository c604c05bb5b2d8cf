/* Structs that cross the host/device boundary: one definition, valid C++ and OpenCL C.
 * Only 4-byte scalars, explicit padding, sizes pinned by static_asserts (host) and a layout
 * test that runs on the device (tests/kernels). Included by .cl files via the host's
 * program assembler (host/cl), which inlines "shared/rc_types.h". */
#ifndef RC_TYPES_H
#define RC_TYPES_H

#ifdef __OPENCL_VERSION__
typedef int rc_int;
typedef uint rc_uint;
#else
#include <cstdint>
typedef int32_t rc_int;
typedef uint32_t rc_uint;
#endif

/* One contributing record for one shading point (interpolate kernel). Points list their
 * contributions in CSR form: entries[offsets[p] .. offsets[p+1]). */
typedef struct RcContribution {
  rc_int record;  /* index into the record arrays */
  float weight;   /* w_i(p) > 0, unnormalised */
  float dt, db;   /* displacement p - p_i projected on the record's tangent t_i and bitangent b_i */
} RcContribution;

/* Describes one material's BRDF×cos coefficient table inside the flat table array (brdf_dot). */
typedef struct RcBrdfTable {
  rc_int kind;    /* RC_TABLE_ISOTROPIC_1D or RC_TABLE_ANISOTROPIC_2D */
  rc_int order;   /* SH order n of the table; n² coefficients per channel */
  rc_int res;     /* T entries (1-D) or S×S entries (2-D) */
  rc_int offset;  /* first float of the table in the flat array */
} RcBrdfTable;

/* One nonzero of the x-90° SH rotation's band blocks (sh_rotate, interpolate): three quarters of
 * those blocks are structural zeros, so the kernels walk rows in CSR form, entries
 * rowStart[i] .. rowStart[i+1]), column = flat SH index of the coefficient it multiplies. */
typedef struct RcSparseEntry {
  rc_int column;
  float value;
} RcSparseEntry;

#define RC_TABLE_ISOTROPIC_1D 0
#define RC_TABLE_ANISOTROPIC_2D 1

#ifndef __OPENCL_VERSION__
static_assert(sizeof(RcContribution) == 16, "RcContribution layout");
static_assert(sizeof(RcBrdfTable) == 16, "RcBrdfTable layout");
static_assert(sizeof(RcSparseEntry) == 8, "RcSparseEntry layout");
#endif

#endif /* RC_TYPES_H */

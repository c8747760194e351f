// polyDEM: host/device qualifiers shared by both back ends.
// The same source is compiled by nvcc (CUDA back end) and by g++ with
// Thrust's OpenMP system (CPU back end); there the qualifiers vanish.
#pragma once

#if defined(__CUDACC__)
#define PD_HD __host__ __device__
#define PD_INLINE __host__ __device__ __forceinline__
#else
#define PD_HD
#define PD_INLINE inline
#endif

#pragma once
/// Marks the functions of the core's per-sample paths as callable from CUDA
/// kernels (docs/gpu.md): `__host__ __device__` when nvcc compiles, nothing
/// for a host compiler. Constructors stay host-only: they validate and may
/// throw; what a kernel calls never throws and never allocates.
///
/// Tables. A host `constexpr` array indexed from device code compiles, with
/// no diagnostic, to a trap or to loads from its host offset; so every table
/// a per-sample path reads has a device copy (`STRATUM_DEVICE_TABLE`,
/// selected under __CUDA_ARCH__) or is held by pointer in a view the host
/// fills (Sobol, the base-b digit scramblers).
#if defined(__CUDACC__)
#define STRATUM_HOST_DEVICE __host__ __device__
/// A read-only device copy of a constexpr table: one per translation unit
/// (internal linkage, as nvcc's whole-program mode requires).
#define STRATUM_DEVICE_TABLE static __device__ const
#else
#define STRATUM_HOST_DEVICE
#endif

#pragma once
// A run's state as a VTK file and back, from the registries alone (no array is named here):
//
//   points                  the field "position" (x^n), padded to 3D
//   point data, display     every display field under its physical name: scalars, vectors as
//                           3 components (2D, 1D: zeros for the missing ones), tensors as 3×3
//                           with components named XX .. ZZ; double precision unless the field
//                           says otherwise; the active scalars/vectors/tensors set
//   point data, restart     restart-only fields as "restart:<name>", their native D, D×D or
//                           D×D×D components in double precision
//   field data              "TimeValue" (ParaView's time) and every run scalar and run
//                           array as "restart:<name>"
//   ragged particle fields  (particles/RaggedArray.hpp) each particle's entry count as the
//                           point array "restart:<name>Count", the entries of the written
//                           particles in their order as the field data "restart:<name>"
//                           (one tuple per entry; io/PvtuFile joins a distributed run's
//                           pieces' entries in the points' order)
//
// Reading puts back every restart field (from its display array when it is also displayed:
// the padding is exact) and every run scalar; anything missing or of another shape is an
// InputError naming the file.

#include "core/RunScalars.hpp"
#include "io/VtuFile.hpp"
#include "particles/ParticleFields.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace sph
{

// The name of the field written as the points.
inline constexpr const char* positionField = "position";

// Everything but the points: the field data (time, run scalars and arrays, the ragged
// fields' entries of the written particles: every particle, or those of `selection`) and the
// active arrays. The ragged fields' entries are streamed (VtuStreamedValues): they read
// `fields` and `selection` when the file is written, so write it before either changes.
template <int D>
void writeStateHeader(const ParticleFields<D>& fields, const RunScalars& scalars, double time,
                      VtuData& header, const std::vector<std::size_t>* selection = nullptr);

// The written points [begin, end) and their point arrays: written point k is particle k, or
// particle (*selection)[k] (a distributed run writes its owned particles only). With
// io/VtuFile's writeVtuInPieces, a piece at a time.
template <int D>
void writeStatePoints(const ParticleFields<D>& fields, const std::vector<std::size_t>* selection,
                      std::size_t begin, std::size_t end, VtuData& piece);

// Both, for every particle, into one data set that holds every value (nothing streamed).
template <int D>
void writeState(const ParticleFields<D>& fields, const RunScalars& scalars, double time,
                VtuData& data);

// Reads every restart field and run scalar of `data` (from `file`, for messages).
template <int D>
void readState(const VtuData& data, ParticleFields<D>& fields, const RunScalars& scalars,
               const std::string& file);

} // namespace sph

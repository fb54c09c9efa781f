#pragma once
// Cephalometric measurements as plain functions of points in the sagittal frame
// (sagittal_projection.h: 2D, mm, u = anterior, v = superior). Angles in degrees.
#include <Eigen/Core>

namespace maxillo::ceph {

// Unsigned angle (0..180 deg) at `vertex` between the rays to a and b.
double angle_at_deg(const Eigen::Vector2d& vertex, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// SNA = angle at N between N->S and N->A; SNB likewise with B. ANB = SNA - SNB (signed:
// negative when B lies in front of A as seen from N, the Class III pattern). The angles are
// unsigned, as in the ISBI 2015 challenge's definition; A and B always lie on the same side
// (below) of the SN line, so ANB keeps its sign.
double sna_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& A);
double snb_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& B);
double anb_deg(const Eigen::Vector2d& S, const Eigen::Vector2d& N, const Eigen::Vector2d& A, const Eigen::Vector2d& B);

// Wits appraisal (mm): A and B projected perpendicularly on the occlusal line through
// `occlusal_posterior` and `occlusal_anterior`; the distance AO - BO measured along the line
// towards anterior. Positive when AO lies in front of BO (Class II), negative in Class III,
// about 0 mm in a normal sagittal relationship (Jacobson 1975).
double wits_mm(const Eigen::Vector2d& A, const Eigen::Vector2d& B, const Eigen::Vector2d& occlusal_posterior,
               const Eigen::Vector2d& occlusal_anterior);

// The source's nasion frame (thesis ch. 5, Fig. 8): origin N; X axis through N, the S->N line
// rotated by 6 deg so that its anterior end goes down (the posterior part rises above S), which
// brings it close to Frankfort horizontal (SN rises ~7 deg anteriorly above FH); Y axis
// perpendicular to X through N. Signs as in the source's Table II: X positive ANTERIOR, Y
// positive INFERIOR (anterior and inferior displacements are positive).
inline constexpr double kNasionFrameRotationDeg = 6;
struct NasionFrame {
  Eigen::Vector2d origin;  // N
  Eigen::Vector2d x_axis;  // unit, anterior (sagittal frame components)
  Eigen::Vector2d y_axis;  // unit, inferior
};
NasionFrame nasion_frame(const Eigen::Vector2d& S, const Eigen::Vector2d& N);
// (X, Y) of p in the nasion frame, mm.
Eigen::Vector2d in_nasion_frame(const NasionFrame& frame, const Eigen::Vector2d& p);

// Palatal plane angle alpha = angle between the Y axis and the palatal plane PNS->ANS,
// atan2(dX, dY) of PNS->ANS in the nasion frame (about 90 deg when the palatal plane parallels
// X). Upward rotation of the palatal plane (ANS rising relative to PNS) increases alpha:
// upward rotations positive, downward negative, as in the source's Table III.
double palatal_angle_alpha_deg(const NasionFrame& frame, const Eigen::Vector2d& ANS, const Eigen::Vector2d& PNS);

}  // namespace maxillo::ceph

// The analytic model of window sampling (Marks, Walsh, Christensen & Friedell, GI '90,
// sections 2 and 3): window samples of the Warnock algorithm on the ideal scene (Eqs. 2.1-2.4)
// and the cost per pixel of the cheapest window derived from a window (Exprs. 2.5-2.7, 3.1).
//
// Each quantity comes twice:
//  - the closed form the paper prints, on doubles, because the paper applies it to real
//    scenes with non-integer F_v and E_f;
//  - the recurrence it was derived from, on exact integers, defined only on the ideal scene
//    (F_v a power of 4, edges powers of 2), so tests can check one against the other.
//
// Domain: the closed forms never throw. Outside the ideal scene's domain (F_v < 1, F_w < D,
// E_f < 1 i.e. F_v > E_s^2) they return whatever the formula gives (NaN for non-positive
// arguments of sqrt or log), and the predict_* functions clear `valid` and say why in
// `note`. The recurrences throw std::invalid_argument off their domain (a caller's bug).
// Eq. 5.2 (form factors) is not part of this model. See docs/MODEL.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace fb89::host::model {

// --- closed forms, as printed -------------------------------------------------------------

// Eq. 2.1: sorting-phase samples until every window holds one visible face, (F_v - 1) / 3.
double sort_samples(double f_v);
// Splitting samples of a window with a 1/2-pixel gap along one edge of length n: 4n - 3.
double split_1edge_samples(double n);
// Eq. 2.3: splitting samples of a window holding one face of edge E_f with gaps along two
// edges: 8 E_f - 4 log2 E_f - 7.
double split_samples(double e_f);
// E_f = sqrt(E_s^2 / F_v), the face edge of the ideal scene (the 1/2-pixel gap ignored).
double face_edge(double e_s, double f_v);
// Eq. 2.4: S(F_v) = (F_v - 1)/3 + 8 E_s sqrt(F_v) - 4 F_v log2 sqrt(E_s^2 / F_v) - 7 F_v, the
// window samples of an E_s x E_s screen with F_v visible faces. Independent of D.
double window_samples(double e_s, double f_v);

// C_sort(F_w) = F_w log4(F_w / D): face computations (sorting a face into a subwindow) of
// the sorting phase in a window of F_w faces and depth complexity D.
double sort_face_computations(double f_w, double d);
// The whole ideal scene's sorting phase: F log4 F_v with F = D F_v faces.
double scene_sort_face_computations(double f_v, double d);

// F_vw = F_w / D and E_fw = sqrt(E_w^2 D / F_w), the identities behind Exprs. 2.6 and 2.7.
double window_visible_faces(double f_w, double d);
double window_face_edge(double e_w, double f_w, double d);

// Expr. 2.5: face computations per pixel of the largest windows rendered by one sample,
// (C_sort(F_w) / F_vw + D) / (E_fw^2 / 4), before the identities above are substituted.
double expr_2_5(double f_w, double d, double f_vw, double e_fw);
// Expr. 2.6: Expr. 2.5 with the identities substituted, (4 F_w log4(F_w/D) + 4 F_w) / E_w^2.
double expr_2_6(double f_w, double d, double e_w);
// Expr. 3.1: the hybrid's estimate, Expr. 2.6 / 4 = (F_w log4(F_w/D) + F_w) / E_w^2.
double expr_3_1(double f_w, double d, double e_w);
// Expr. 3.1 for a window of any shape: E_w^2 is its area in pixels (the hybrid's form).
double expr_3_1_area(double f_w, double d, double area);
// Samples per rendered pixel when every sample costs the same (the unnumbered expression
// before 2.7): ((F_vw - 1) / (3 F_vw) + 5) / (E_fw^2 / 4).
double samples_per_rendered_pixel(double f_vw, double e_fw);
// Expr. 2.7: F (16 F_w - D) / (E_w^2 D), the cost per pixel when each sample costs time
// proportional to all F faces (beam tracing). The paper drops a constant: it equals
// (3/4) F samples_per_rendered_pixel(F_w / D, E_fw).
double expr_2_7(double f, double f_w, double d, double e_w);
// Expr. 2.7 for a window of any shape: E_w^2 is its area in pixels (the beam hybrid's form).
double expr_2_7_area(double f, double f_w, double d, double area);
// Expr. 2.7 solved for F_w: the window face count at which the cost per pixel reaches
// `cost`, (cost E_w^2 D / F + D) / 16 (F taken as at least 1).
double expr_2_7_faces_at(double cost, double f, double d, double area);

// --- exact recurrences on the ideal scene ---------------------------------------------------

// Largest screen edge and face count the recurrences accept (results stay below 2^64).
inline constexpr uint64_t kMaxRecurrenceEdge = uint64_t{1} << 24;
inline constexpr uint64_t kMaxRecurrenceFaces = uint64_t{1} << 48;

// S_sort(F_v) = 1 + 4 S_sort(F_v / 4), S_sort(1) = 0. F_v a power of 4.
uint64_t sort_samples_recurrence(uint64_t f_v);
// S_split_1edge(n) = 3 + 2 S_split_1edge(n / 2), S_split_1edge(1) = 1. n a power of 2.
uint64_t split_1edge_samples_recurrence(uint64_t n);
// S_split(E_f) = 2 + 2 S_split_1edge(E_f / 2) + S_split(E_f / 2), S_split(1) = 1.
uint64_t split_samples_recurrence(uint64_t e_f);
// S_sort(F_v) + F_v S_split(E_s / sqrt(F_v)): E_s a power of 2, F_v a power of 4, F_v <= E_s^2.
uint64_t window_samples_recurrence(uint64_t e_s, uint64_t f_v);
// C_sort(F_w) = F_w + 4 C_sort(F_w / 4), C_sort(D) = 0. F_w = D 4^k, D >= 1.
uint64_t sort_face_computations_recurrence(uint64_t f_w, uint64_t d);

// --- predictions with their domain ----------------------------------------------------------

// Eqs. 2.1-2.4 for one screen, plus the sorting-phase face computations for depth D.
struct SamplePrediction {
    double e_s = 0, f_v = 0, d = 0;
    double e_f = 0;                     // sqrt(E_s^2 / F_v)
    double sort_samples = 0;            // Eq. 2.1
    double split_samples = 0;           // Eq. 2.3 at E_f, per visible face
    double window_samples = 0;          // Eq. 2.4
    double faces = 0;                   // F = D F_v
    double sort_face_computations = 0;  // F log4 F_v
    bool valid = false;                 // E_s > 0, D > 0, 1 <= F_v <= E_s^2 (so E_f >= 1)
    bool ideal = false;  // the recurrences hold exactly: E_s = 2^j, F_v = 4^k, D integral
    std::string note;    // why not valid; empty when valid
    std::string to_string() const;
};
SamplePrediction predict_samples(double e_s, double f_v, double d);

// Exprs. 2.5-2.7 and 3.1 for one window; 2.7 only when the scene's face count F is given.
struct WindowCostPrediction {
    double f_w = 0, d = 0, e_w = 0;
    std::optional<double> f;
    double f_vw = 0, e_fw = 0;  // F_w / D, sqrt(E_w^2 D / F_w)
    double expr_2_5 = 0, expr_2_6 = 0, expr_3_1 = 0;
    std::optional<double> expr_2_7;
    bool valid = false;  // D > 0, F_w >= D (log4(F_w/D) >= 0), E_fw >= 1
    std::string note;
    std::string to_string() const;
};
WindowCostPrediction predict_window_cost(double f_w, double d, double e_w,
                                         std::optional<double> f = std::nullopt);

}  // namespace fb89::host::model

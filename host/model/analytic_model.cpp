// The analytic model of window sampling, Marks et al. 1990: Eqs. 2.1-2.4 (window samples of
// the ideal scene), the sorting-phase face computations, Exprs. 2.5-2.7 and 3.1 (cost per
// pixel). Closed forms are transcribed as printed; the recurrences are written literally,
// one recursive call per term of the paper's recurrence, so each checks the other.
#include "host/model/analytic_model.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::host::model {

namespace {

bool is_power_of_two(uint64_t x) {
    return x != 0 && (x & (x - 1)) == 0;
}

bool is_power_of_four(uint64_t x) {
    return is_power_of_two(x) && (x & 0x5555555555555555ull) != 0;
}

double log4(double x) {
    return std::log2(x) / 2;
}

// Integral and within the recurrences' limits: the double can be handed to them exactly.
bool is_exact_integer(double x, uint64_t limit) {
    return x >= 1 && x <= static_cast<double>(limit) && std::floor(x) == x;
}

void require(bool ok, const char* what, uint64_t value, const char* expected) {
    if (!ok)
        throw std::invalid_argument(fmt::format("{} = {}: expected {}", what, value, expected));
}

}  // namespace

// --- closed forms ---------------------------------------------------------------------------

double sort_samples(double f_v) {
    return (f_v - 1) / 3;
}

double split_1edge_samples(double n) {
    return 4 * n - 3;
}

double split_samples(double e_f) {
    return 8 * e_f - 4 * std::log2(e_f) - 7;
}

double face_edge(double e_s, double f_v) {
    return std::sqrt(e_s * e_s / f_v);
}

double window_samples(double e_s, double f_v) {
    return (f_v - 1) / 3 + 8 * e_s * std::sqrt(f_v) -
           4 * f_v * std::log2(std::sqrt(e_s * e_s / f_v)) - 7 * f_v;
}

double sort_face_computations(double f_w, double d) {
    return f_w * log4(f_w / d);
}

double scene_sort_face_computations(double f_v, double d) {
    return d * f_v * log4(f_v);
}

double window_visible_faces(double f_w, double d) {
    return f_w / d;
}

double window_face_edge(double e_w, double f_w, double d) {
    return std::sqrt(e_w * e_w * d / f_w);
}

double expr_2_5(double f_w, double d, double f_vw, double e_fw) {
    return (sort_face_computations(f_w, d) / f_vw + d) / (e_fw * e_fw / 4);
}

double expr_2_6(double f_w, double d, double e_w) {
    return (4 * f_w * log4(f_w / d) + 4 * f_w) / (e_w * e_w);
}

double expr_3_1(double f_w, double d, double e_w) {
    return expr_3_1_area(f_w, d, e_w * e_w);
}

double expr_3_1_area(double f_w, double d, double area) {
    return (f_w * log4(f_w / d) + f_w) / area;
}

double samples_per_rendered_pixel(double f_vw, double e_fw) {
    return ((f_vw - 1) / (3 * f_vw) + 5) / (e_fw * e_fw / 4);
}

double expr_2_7(double f, double f_w, double d, double e_w) {
    return expr_2_7_area(f, f_w, d, e_w * e_w);
}

double expr_2_7_area(double f, double f_w, double d, double area) {
    return f * (16 * f_w - d) / (area * d);
}

double expr_2_7_faces_at(double cost, double f, double d, double area) {
    return (cost * area * d / std::max(f, 1.0) + d) / 16;
}

// --- recurrences ----------------------------------------------------------------------------

uint64_t sort_samples_recurrence(uint64_t f_v) {
    require(is_power_of_four(f_v) && f_v <= kMaxRecurrenceFaces, "F_v", f_v,
            "a power of 4 up to 4^24");
    if (f_v == 1) return 0;
    return 1 + 4 * sort_samples_recurrence(f_v / 4);
}

uint64_t split_1edge_samples_recurrence(uint64_t n) {
    require(is_power_of_two(n) && n <= kMaxRecurrenceEdge, "n", n, "a power of 2 up to 2^24");
    if (n == 1) return 1;
    return 3 + 2 * split_1edge_samples_recurrence(n / 2);
}

uint64_t split_samples_recurrence(uint64_t e_f) {
    require(is_power_of_two(e_f) && e_f <= kMaxRecurrenceEdge, "E_f", e_f,
            "a power of 2 up to 2^24");
    if (e_f == 1) return 1;
    return 2 + 2 * split_1edge_samples_recurrence(e_f / 2) + split_samples_recurrence(e_f / 2);
}

uint64_t window_samples_recurrence(uint64_t e_s, uint64_t f_v) {
    require(is_power_of_two(e_s) && e_s <= kMaxRecurrenceEdge, "E_s", e_s,
            "a power of 2 up to 2^24");
    require(is_power_of_four(f_v) && f_v <= e_s * e_s, "F_v", f_v, "a power of 4 up to E_s^2");
    // sqrt(F_v) = 2^k for F_v = 4^k, so E_f = E_s / 2^k exactly
    int k = std::countr_zero(f_v) / 2;
    uint64_t e_f = e_s >> k;
    return sort_samples_recurrence(f_v) + f_v * split_samples_recurrence(e_f);
}

uint64_t sort_face_computations_recurrence(uint64_t f_w, uint64_t d) {
    require(d >= 1 && d <= kMaxRecurrenceFaces, "D", d, "at least 1");
    require(f_w % d == 0 && is_power_of_four(f_w / d) && f_w <= kMaxRecurrenceFaces, "F_w", f_w,
            "D times a power of 4");
    if (f_w == d) return 0;
    return f_w + 4 * sort_face_computations_recurrence(f_w / 4, d);
}

// --- predictions ----------------------------------------------------------------------------

SamplePrediction predict_samples(double e_s, double f_v, double d) {
    SamplePrediction p;
    p.e_s = e_s;
    p.f_v = f_v;
    p.d = d;
    p.e_f = face_edge(e_s, f_v);
    p.sort_samples = sort_samples(f_v);
    p.split_samples = split_samples(p.e_f);
    p.window_samples = window_samples(e_s, f_v);
    p.faces = d * f_v;
    p.sort_face_computations = scene_sort_face_computations(f_v, d);

    // domain, first failure wins
    if (!(e_s > 0))
        p.note = "E_s <= 0: no screen";
    else if (!(d > 0))
        p.note = "D <= 0: no faces";
    else if (!(f_v >= 1))
        p.note = "F_v < 1: fewer than one visible face, S_sort < 0";
    else if (!(f_v <= e_s * e_s))
        p.note = "E_f < 1 (F_v > E_s^2): faces smaller than a pixel, below where subdivision stops";
    p.valid = p.note.empty();

    p.ideal =
        p.valid && is_exact_integer(e_s, kMaxRecurrenceEdge) &&
        is_power_of_two(static_cast<uint64_t>(e_s)) && is_exact_integer(f_v, kMaxRecurrenceFaces) &&
        is_power_of_four(static_cast<uint64_t>(f_v)) && is_exact_integer(d, kMaxRecurrenceFaces);
    return p;
}

std::string SamplePrediction::to_string() const {
    return fmt::format(
        "E_s={} F_v={} D={}: E_f={} S_sort={} S_split={} S={} F={} C_sort={} valid={} ideal={}{}",
        e_s, f_v, d, e_f, sort_samples, split_samples, window_samples, faces,
        sort_face_computations, valid, ideal, note.empty() ? "" : " (" + note + ")");
}

WindowCostPrediction predict_window_cost(double f_w, double d, double e_w,
                                         std::optional<double> f) {
    WindowCostPrediction p;
    p.f_w = f_w;
    p.d = d;
    p.e_w = e_w;
    p.f = f;
    p.f_vw = window_visible_faces(f_w, d);
    p.e_fw = window_face_edge(e_w, f_w, d);
    p.expr_2_5 = expr_2_5(f_w, d, p.f_vw, p.e_fw);
    p.expr_2_6 = expr_2_6(f_w, d, e_w);
    p.expr_3_1 = expr_3_1(f_w, d, e_w);
    if (f) p.expr_2_7 = expr_2_7(*f, f_w, d, e_w);

    // domain, first failure wins
    if (!(e_w > 0))
        p.note = "E_w <= 0: no window";
    else if (!(d > 0))
        p.note = "D <= 0: no depth";
    else if (!(f_w >= d))
        p.note = "F_w < D: log4(F_w/D) < 0, fewer faces than layers";
    else if (!(p.e_fw >= 1))
        p.note = "E_fw < 1 (F_w/D > E_w^2): faces smaller than a pixel";
    else if (f && !(*f >= f_w))
        p.note = "F < F_w: the scene has fewer faces than the window";
    p.valid = p.note.empty();
    return p;
}

std::string WindowCostPrediction::to_string() const {
    return fmt::format("F_w={} D={} E_w={}: F_vw={} E_fw={} 2.5={} 2.6={} 3.1={} 2.7={} valid={}{}",
                       f_w, d, e_w, f_vw, e_fw, expr_2_5, expr_2_6, expr_3_1,
                       expr_2_7 ? fmt::format("{}", *expr_2_7) : "-", valid,
                       note.empty() ? "" : " (" + note + ")");
}

}  // namespace fb89::host::model

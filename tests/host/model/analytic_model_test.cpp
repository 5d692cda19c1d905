// The analytic model (Marks et al. 1990, Eqs. 2.1-2.7, Expr. 3.1): the paper's closed forms
// against the recurrences they come from, the sanity values of REFERENCES.md, the sums in
// the middle of each derivation, and the domain edge cases.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "host/model/analytic_model.h"

namespace fb89::host::model {
namespace {

constexpr uint64_t pow2(int k) {
    return uint64_t{1} << k;
}

// --- sanity values -------------------------------------------------------------------------

TEST(AnalyticModel, SplitOfOnePixelFaceIsOneSample) {
    EXPECT_EQ(split_samples_recurrence(1), 1u);
    EXPECT_EQ(split_samples(1), 1.0);
}

TEST(AnalyticModel, SplitOfTwoPixelFaceIsFiveSamples) {
    EXPECT_EQ(split_samples_recurrence(2), 5u);
    EXPECT_EQ(split_samples(2), 5.0);
}

TEST(AnalyticModel, Split1EdgeIsFourNMinusThree) {
    for (int k = 0; k <= 24; ++k) {
        EXPECT_EQ(split_1edge_samples_recurrence(pow2(k)), 4 * pow2(k) - 3) << "n = 2^" << k;
        EXPECT_EQ(split_1edge_samples(static_cast<double>(pow2(k))),
                  static_cast<double>(4 * pow2(k) - 3));
    }
}

TEST(AnalyticModel, Eq24GivesThe1685SamplesOfEs64Fv16) {
    EXPECT_EQ(window_samples(64, 16), 1685.0);
    EXPECT_EQ(window_samples_recurrence(64, 16), 1685u);
}

TEST(AnalyticModel, Eq24GivesThe17749SamplesOfEs128Fv1024) {
    EXPECT_EQ(window_samples(128, 1024), 17749.0);
    EXPECT_EQ(window_samples_recurrence(128, 1024), 17749u);
}

TEST(AnalyticModel, Eq24GivesThe21845SamplesOfEs128Fv16384WhereEfIsOne) {
    EXPECT_EQ(face_edge(128, 16384), 1.0);
    EXPECT_EQ(window_samples(128, 16384), 21845.0);
    EXPECT_EQ(window_samples_recurrence(128, 16384), 21845u);
}

TEST(AnalyticModel, Eq24AtEfOneIsSortPlusOneSamplePerFace) {
    // E_f = 1: no splitting, one sample per visible face: (F_v - 1)/3 + F_v = (4 F_v - 1)/3
    for (int j = 4; j <= 10; ++j) {
        double e_s = static_cast<double>(pow2(j)), f_v = e_s * e_s;
        EXPECT_EQ(window_samples(e_s, f_v), (4 * f_v - 1) / 3) << "E_s = " << e_s;
    }
}

TEST(AnalyticModel, Eq24AtOneVisibleFaceIsSplitOfTheScreen) {
    for (int j = 0; j <= 10; ++j) {
        double e_s = static_cast<double>(pow2(j));
        EXPECT_EQ(window_samples(e_s, 1), split_samples(e_s)) << "E_s = " << e_s;
    }
    EXPECT_EQ(window_samples(1024, 1), 8145.0);  // 8*1024 - 4*10 - 7
}

// --- closed forms against recurrences -------------------------------------------------------

TEST(AnalyticModel, Eq21ClosedFormEqualsRecurrenceForPowersOfFour) {
    for (int k = 0; k <= 24; ++k) {
        uint64_t f_v = pow2(2 * k);
        EXPECT_EQ(sort_samples(static_cast<double>(f_v)),
                  static_cast<double>(sort_samples_recurrence(f_v)))
            << "F_v = 4^" << k;
    }
}

TEST(AnalyticModel, Eq23ClosedFormEqualsRecurrenceForPowersOfTwo) {
    for (int k = 0; k <= 24; ++k) {
        uint64_t e_f = pow2(k);
        EXPECT_EQ(split_samples(static_cast<double>(e_f)),
                  static_cast<double>(split_samples_recurrence(e_f)))
            << "E_f = 2^" << k;
    }
}

TEST(AnalyticModel, Eq24ClosedFormEqualsRecurrenceForEs16To1024AndEveryPowerOfFourFv) {
    int checked = 0;
    for (uint64_t e_s = 16; e_s <= 1024; e_s *= 2)
        for (uint64_t f_v = 1; f_v <= e_s * e_s; f_v *= 4) {
            double closed = window_samples(static_cast<double>(e_s), static_cast<double>(f_v));
            EXPECT_EQ(closed, static_cast<double>(window_samples_recurrence(e_s, f_v)))
                << "E_s = " << e_s << ", F_v = " << f_v;
            ++checked;
        }
    EXPECT_EQ(checked, 5 + 6 + 7 + 8 + 9 + 10 + 11);
}

TEST(AnalyticModel, Eq24IsSortPlusFvTimesSplitOfFaceEdge) {
    for (double e_s : {100.0, 780.0, 1024.0})
        for (double f_v : {1.0, 2.5, 37.0, 1000.0, 9999.0}) {
            double composed = sort_samples(f_v) + f_v * split_samples(face_edge(e_s, f_v));
            EXPECT_NEAR(window_samples(e_s, f_v), composed, 1e-9 * composed)
                << "E_s = " << e_s << ", F_v = " << f_v;
        }
}

TEST(AnalyticModel, SortFaceComputationsClosedFormEqualsRecurrence) {
    for (uint64_t d : {1u, 2u, 3u, 4u, 7u})
        for (int k = 0; k <= 12; ++k) {
            uint64_t f_w = d * pow2(2 * k);
            EXPECT_EQ(sort_face_computations(static_cast<double>(f_w), static_cast<double>(d)),
                      static_cast<double>(sort_face_computations_recurrence(f_w, d)))
                << "F_w = " << f_w << ", D = " << d;
        }
}

TEST(AnalyticModel, SceneSortFaceComputationsAreFLog4FvWithFEqualsDFv) {
    EXPECT_EQ(scene_sort_face_computations(1024, 4), 4 * 1024 * 5.0);
    EXPECT_EQ(scene_sort_face_computations(1024, 4), sort_face_computations(4096, 4));
    EXPECT_EQ(scene_sort_face_computations(1, 3), 0.0);
}

// --- the sums in the middle of each derivation ----------------------------------------------

TEST(AnalyticModel, Eq21SumOfPowersOfFourEqualsRecurrence) {
    for (int k = 0; k <= 12; ++k) {
        uint64_t sum = 0;
        for (int i = 0; i <= k - 1; ++i)
            sum += pow2(2 * i);
        EXPECT_EQ(sum, sort_samples_recurrence(pow2(2 * k))) << "F_v = 4^" << k;
    }
}

TEST(AnalyticModel, Split1EdgeSumEqualsRecurrence) {
    for (int k = 0; k <= 20; ++k) {
        uint64_t sum = pow2(k);  // 3 sum_{i=0}^{log2 n - 1} 2^i + n
        for (int i = 0; i <= k - 1; ++i)
            sum += 3 * pow2(i);
        EXPECT_EQ(sum, split_1edge_samples_recurrence(pow2(k))) << "n = 2^" << k;
    }
}

TEST(AnalyticModel, Eq22SumEqualsRecurrence) {
    for (int k = 0; k <= 20; ++k) {
        uint64_t e_f = pow2(k);  // 2 sum_{i=1}^{log2 E_f} S_1edge(E_f / 2^i) + 2 log2 E_f + 1
        uint64_t sum = 2 * static_cast<uint64_t>(k) + 1;
        for (int i = 1; i <= k; ++i)
            sum += 2 * split_1edge_samples_recurrence(e_f >> i);
        EXPECT_EQ(sum, split_samples_recurrence(e_f)) << "E_f = 2^" << k;
    }
}

// --- per-window expressions -----------------------------------------------------------------

TEST(AnalyticModel, Expr25WithIdentitiesSubstitutedIsExpr26) {
    for (double d : {1.0, 2.0, 3.3, 8.0})
        for (double f_w : {8.0, 64.0, 1000.0})
            for (double e_w : {16.0, 64.0, 512.0}) {
                double f_vw = window_visible_faces(f_w, d), e_fw = window_face_edge(e_w, f_w, d);
                double e26 = expr_2_6(f_w, d, e_w);
                EXPECT_NEAR(expr_2_5(f_w, d, f_vw, e_fw), e26, 1e-12 * e26)
                    << "F_w = " << f_w << ", D = " << d << ", E_w = " << e_w;
            }
}

TEST(AnalyticModel, Expr31IsAQuarterOfExpr26) {
    for (double d : {1.0, 2.5, 4.0})
        for (double f_w : {4.0, 64.0, 5000.0})
            EXPECT_DOUBLE_EQ(expr_3_1(f_w, d, 32), expr_2_6(f_w, d, 32) / 4);
}

TEST(AnalyticModel, Expr31OfSixtyFourFacesInA32PixelWindowAtDepth4Is0_1875) {
    // (64 log4 16 + 64) / 32^2 = 192 / 1024
    EXPECT_EQ(expr_3_1(64, 4, 32), 0.1875);
    EXPECT_EQ(expr_2_6(64, 4, 32), 0.75);
}

TEST(AnalyticModel, Expr27IsThreeQuartersOfFTimesSamplesPerRenderedPixel) {
    // the paper's "proportional to" drops the constant 4/3 of the exact samples per pixel
    for (double d : {1.0, 2.0, 4.0})
        for (double f_w : {4.0, 64.0, 1024.0}) {
            double f = 10000, e_w = 128;
            double exact = f * samples_per_rendered_pixel(window_visible_faces(f_w, d),
                                                          window_face_edge(e_w, f_w, d));
            EXPECT_NEAR(expr_2_7(f, f_w, d, e_w), 0.75 * exact, 1e-12 * exact)
                << "F_w = " << f_w << ", D = " << d;
        }
}

TEST(AnalyticModel, Expr27OfOneFaceWindowIs15FOverEw2) {
    EXPECT_EQ(expr_2_7(1000, 1, 1, 10), 150.0);  // 1000 (16 - 1) / 100
}

// --- domain ---------------------------------------------------------------------------------

TEST(AnalyticModel, PredictionOfPowerOfTwoScreenIsValidAndIdeal) {
    SamplePrediction p = predict_samples(64, 16, 4);
    EXPECT_TRUE(p.valid) << p.to_string();
    EXPECT_TRUE(p.ideal) << p.to_string();
    EXPECT_EQ(p.e_f, 16.0);
    EXPECT_EQ(p.sort_samples, 5.0);
    EXPECT_EQ(p.split_samples, 105.0);
    EXPECT_EQ(p.window_samples, 1685.0);
    EXPECT_EQ(p.faces, 64.0);
    EXPECT_EQ(p.sort_face_computations, 128.0);
    EXPECT_TRUE(p.note.empty());
}

TEST(AnalyticModel, PredictionOfRealSceneIsValidButNotIdeal) {
    SamplePrediction p = predict_samples(780, 1234.5, 3.3);
    EXPECT_TRUE(p.valid) << p.to_string();
    EXPECT_FALSE(p.ideal);
    EXPECT_TRUE(std::isfinite(p.window_samples));
}

TEST(AnalyticModel, FewerThanOneVisibleFaceIsOutsideTheDomain) {
    SamplePrediction p = predict_samples(64, 0.5, 1);
    EXPECT_FALSE(p.valid);
    EXPECT_NE(p.note.find("F_v < 1"), std::string::npos) << p.note;
    EXPECT_LT(p.sort_samples, 0);  // what the formula gives
    EXPECT_TRUE(std::isnan(window_samples(64, 0)));
}

TEST(AnalyticModel, FacesSmallerThanAPixelAreOutsideTheDomain) {
    SamplePrediction p = predict_samples(64, 4 * 64 * 64, 1);
    EXPECT_FALSE(p.valid);
    EXPECT_FALSE(p.ideal);
    EXPECT_EQ(p.e_f, 0.5);
    EXPECT_NE(p.note.find("E_f < 1"), std::string::npos) << p.note;
    EXPECT_TRUE(std::isfinite(p.window_samples));        // returned, not thrown
    EXPECT_TRUE(predict_samples(64, 64 * 64, 1).valid);  // E_f = 1 is the boundary, inside
}

TEST(AnalyticModel, WindowWithFewerFacesThanLayersIsOutsideTheDomain) {
    WindowCostPrediction p = predict_window_cost(2, 4, 32);
    EXPECT_FALSE(p.valid);
    EXPECT_NE(p.note.find("F_w < D"), std::string::npos) << p.note;
    EXPECT_LT(sort_face_computations(2, 4), 0);  // log4(1/2) < 0, returned as is
}

TEST(AnalyticModel, WindowWithOneVisibleFaceHasNoSortingCost) {
    WindowCostPrediction p = predict_window_cost(4, 4, 32, 100.0);
    EXPECT_TRUE(p.valid) << p.to_string();
    EXPECT_EQ(sort_face_computations(4, 4), 0.0);  // C_sort(D) = 0, the recurrence's base
    EXPECT_EQ(p.expr_3_1, 4.0 / 1024);
    ASSERT_TRUE(p.expr_2_7.has_value());
    EXPECT_EQ(*p.expr_2_7, 100.0 * 60 / (1024 * 4));
}

TEST(AnalyticModel, WindowWithSubPixelFacesIsOutsideTheDomain) {
    WindowCostPrediction p = predict_window_cost(4096, 1, 32);
    EXPECT_FALSE(p.valid);
    EXPECT_NE(p.note.find("E_fw < 1"), std::string::npos) << p.note;
    EXPECT_FALSE(p.expr_2_7.has_value());
}

TEST(AnalyticModel, Expr27IsThePapersCostPerPixelOverAWindowsArea) {
    // F (16 F_w - D) / (E_w^2 D)
    EXPECT_DOUBLE_EQ(expr_2_7_area(18, 2, 1, 64), 18.0 * 31 / 64);
    EXPECT_DOUBLE_EQ(expr_2_7_area(946, 10, 2, 1024), 946.0 * 158 / 2048);
    EXPECT_EQ(expr_2_7_area(946, 10, 2, 1024), expr_2_7(946, 10, 2, 32));
    EXPECT_LT(expr_2_7_area(100, 0, 1.5, 16), 0) << "an empty window: go on with beams";
}

TEST(AnalyticModel, Expr27FacesAtInvertsExpr27) {
    for (double cost : {0.5, 10.0, 1000.0}) {
        const double f_w = expr_2_7_faces_at(cost, 946, 2.5, 48 * 16);
        EXPECT_NEAR(expr_2_7_area(946, f_w, 2.5, 48 * 16), cost, 1e-9 * cost);
    }
}

TEST(AnalyticModel, Expr31OverAnAreaIsExpr31OverASquaresEdge) {
    EXPECT_EQ(expr_3_1_area(64, 4, 1024), expr_3_1(64, 4, 32));
    EXPECT_DOUBLE_EQ(expr_3_1_area(16, 1, 8 * 32), (16 * 2 + 16) / 256.0);
}

TEST(AnalyticModel, RecurrencesRejectNonPowers) {
    EXPECT_THROW(sort_samples_recurrence(8), std::invalid_argument);
    EXPECT_THROW(sort_samples_recurrence(0), std::invalid_argument);
    EXPECT_THROW(split_samples_recurrence(3), std::invalid_argument);
    EXPECT_THROW(split_1edge_samples_recurrence(0), std::invalid_argument);
    EXPECT_THROW(window_samples_recurrence(64, 4 * 64 * 64), std::invalid_argument);
    EXPECT_THROW(window_samples_recurrence(48, 4), std::invalid_argument);
    EXPECT_THROW(sort_face_computations_recurrence(12, 4), std::invalid_argument);
    EXPECT_THROW(sort_face_computations_recurrence(4, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fb89::host::model

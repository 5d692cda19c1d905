#include "experiments/catalog.h"

namespace fb89::experiments {

namespace {

const std::vector<std::string_view> kAtoF{"A.json", "B.json", "C.json",
                                          "D.json", "E.json", "F.json"};
const std::vector<std::string_view> kRooms{"garish_room.json", "programmers_cell.json",
                                           "exhibition_hall.json"};

const std::vector<ExperimentInfo>& catalog() {
    static const std::vector<ExperimentInfo> all{
        {"fig2.1", "Warnock vs scan-line vs Z-buffer: time, counts, controller (Fig. 2.1)", kAtoF},
        {"fig2.4", "Eq. 2.4's window samples against an instrumented Warnock (Fig. 2.4)", kAtoF},
        {"fig3.1",
         "the hybrid's time against its Expr. 3.1 threshold (Fig. 3.1)",
         {"A.json", "F.json"}},
        {"hybrid",
         "the calibrated hybrid and the paper's 0.04 against the Z-buffer (§3)",
         {"demo.json", "cornell_box.json", "A.json", "B.json", "C.json", "D.json", "E.json",
          "F.json"}},
        {"accuracy", "exact and approximate fills: time, commands, pixels wrong", kAtoF},
        {"fig4.7",
         "beam-ray frames with the ray-traced pixels blacked out (Figs. 4.7, 4.10)",
         {"G.json", "H.json", "I.json"}},
        {"fig4.8", "beam-ray hybrid vs ray tracer against resolution on G (Fig. 4.8)", {"G.json"}},
        {"fig4.11", "the same on H (Fig. 4.11)", {"H.json"}},
        {"fig4.12", "the same on I (§4's image I)", {"I.json"}},
        {"beam-threshold",
         "time and pixels by beams against the Expr. 2.7 threshold",
         {"G.json", "H.json", "I.json", "cornell_mirror.json"}},
        {"successors",
         "after the paper: hierarchical Z-buffer vs Z-buffer and §3 hybrid, by depth complexity",
         kAtoF},
        {"successors-rays",
         "after the paper: multi-level ray tracing vs ray tracer and §4 beam-ray hybrid, by size",
         {"G.json", "H.json", "I.json", "cornell_box.json", "cornell_mirror.json"}},
        {"split",
         "host vs controller per frame, every method on every bundled scene",
         {"A.json", "B.json", "C.json", "D.json", "E.json", "F.json", "G.json", "H.json", "I.json",
          "demo.json", "cornell_box.json", "cornell_mirror.json", "garish_room.json",
          "programmers_cell.json", "exhibition_hall.json"}},
        {"radiosity", "flux tracing vs decahedral hybrid: rays, queries, time (§5's table)",
         kRooms},
        {"ff-error", "form-factor error against time per method", kRooms},
        {"radiosity-error", "form-factor and radiosity error against time per method", kRooms},
    };
    return all;
}

}  // namespace

std::span<const ExperimentInfo> experiment_catalog() {
    return catalog();
}

const ExperimentInfo* find_experiment(std::string_view name) {
    for (const ExperimentInfo& e : catalog())
        if (e.name == name) return &e;
    return nullptr;
}

}  // namespace fb89::experiments

// Hierarchical radiosity: Hanrahan, Salzman and Aupperle, "A Rapid Hierarchical Radiosity
// Algorithm", SIGGRAPH 91, §5's successor. The same intervisibility coherence the decahedral
// queries look for, used another way: two pieces of surface interact at the coarsest level of
// their hierarchies where the error of doing so is small, so k input faces and n elements make
// O(k² + n) links instead of n² patch pairs, and each face is meshed only as finely as the light
// falling on it needs.
//
// What it does here:
//   - each element of the input mesh (the scene's faces, as mesh.h cuts them into planar quads
//     and triangles, one per face piece) is the root of a tree over its parameter square;
//     a node splits into 2 x 2 children, or 2 across its long side when one side is more than
//     twice the other (so long thin walls get square-ish elements);
//   - Refine(receiver p, source q), for every ordered pair of roots that face each other: the
//     oracle estimates F_pq unoccluded by the disk form between the nodes' centres
//     (A_q cos θp cos θq / (π r² + A_q), the cosines taken as 1 where the nodes are closer than
//     their size, so that it never under-estimates near a shared edge) and refines while
//     ρ_p B_q F_pq — the radiosity the link could put on p — is above ε times the largest
//     emission (BF refinement). The node with the larger area is split (F_pq > F_qp exactly when
//     A_q > A_p); a node at the minimum area is not; when neither can split, they link;
//   - a link's form factor is the exact unoccluded polygon-to-polygon factor (exact.h) times
//     its visibility: the share of k rays, between points spread over both nodes, that the
//     flux tracer's own segment query (visibility.h's FluxTracer::blocked) finds clear, so
//     "rays cast" means what it means for flux tracing. k = 1 casts centre to centre;
//   - solving: gather along every node's links from the sources' current radiosity, then
//     push-pull (radiosity gathered at a node is pushed to its leaves, and each node's
//     radiosity is the area average of its children's), repeated until no leaf changes by more
//     than the tolerance times the largest emission (the other solvers' test);
//   - BF refinement is iterative: after each solve, every link is judged again with the new
//     radiosities and split where it now carries too much, then solved again, until nothing is
//     split or `max_passes` is reached.
//
// How ours differs from the paper: the link factor is exact (theirs was the disk estimate that
// ours uses only as the oracle); visibility is by k rays through the flux tracer's grid rather
// than their ray caster; trees are over the mesh's planar elements (one per face piece) rather
// than input quadrilaterals only; budgets on nodes and links stop refinement (with a note)
// instead of running out of memory as ε → 0, where links grow as n² again (Garmann 1995).
// Shaft culling (Haines and Wallace 1991, the decahedral query's descendant) is an option: before
// a link casts its rays, the shaft between the two nodes' bounding boxes (their union box cut
// by planes through an edge of each) is tested against every other piece's bounding box, and a
// link no piece can block is clear without rays. The shaft holds every segment between the
// nodes, so the links, their factors and the radiosities are the same either way; only rays are
// saved (and box tests spent). Ours tests the scene's pieces in a flat list, without the
// candidate lists a parent link could pass its children. No clustering (Smits, Arvo and
// Salesin 1992).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "host/progress.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/solver.h"
#include "host/radiosity/visibility.h"

namespace fb89::host {

struct HierarchicalOptions {
    double epsilon = 0.01;       // BF refinement: of the largest emission
    double min_area = 0;         // nodes at most this area are not split (0: no limit but depth)
    int link_rays = 4;           // rays per link for its visibility (1: centre to centre)
    bool shaft_culling = false;  // a link whose shaft no other piece meets casts no rays
    int max_passes = 8;          // BF refinement passes (solve, then judge the links again)
    double tolerance = 1e-4;     // of the largest emission, as the other solvers
    int max_iterations = 1000;
    uint64_t max_nodes = 2'000'000;  // budgets: refinement stops where one would be passed
    uint64_t max_links = 20'000'000;
};

struct HierarchicalCounts {
    uint64_t roots = 0;         // input elements
    uint64_t nodes = 0;         // elements in every tree, roots included
    uint64_t leaves = 0;        // the elements drawn
    uint64_t links = 0;         // links at the end
    uint64_t refinements = 0;   // times the oracle asked for a split and one was made
    uint64_t oracle_calls = 0;  // form-factor estimates with the BF test
    uint64_t form_factors = 0;  // exact link factors computed (links made, over all passes)
    uint64_t rays = 0;          // visibility rays, all passes
    uint64_t shafts = 0;        // with shaft culling: shafts built (one a link's visibility)
    uint64_t shafts_clear = 0;  // of them, those no other piece met: links without rays
    uint64_t shaft_tests = 0;   // piece boxes tested against shafts
    int passes = 0;             // refinement passes run (the first included)
    int solve_iterations = 0;   // gather and push-pull sweeps, all passes
    bool budget_hit = false;
};

struct HierarchicalResult {
    Mesh leaves;                 // one one-patch element per leaf, in tree order
    RadiositySolution solution;  // per leaf
    HierarchicalCounts counts;
    RowSums rows;  // each leaf's form factors summed over its links and its ancestors'
    std::vector<std::string> notes;
};

// `mesh` gives the roots: each of its elements, whatever its patch grid. Throws
// std::invalid_argument for options out of range.
HierarchicalResult hierarchical_radiosity(const Mesh& mesh, const RadiosityWorld& world,
                                          const HierarchicalOptions& options,
                                          const WorkObserver& work = {});

}  // namespace fb89::host

#pragma once

// The measurement scenes' dimensions, masses and launch values: one source
// of truth for the ODE programs, the peer-engine programs (peers/) and the
// lab, which reads them back from the programs' metrics. Units are SI.
//
// Each scene has its own namespace below; keep them apart so that one
// scene's edits never touch another's.

namespace odelab::scene {

// ---- test2: Pendulum ---------------------------------------------------------
namespace test2 {
}  // namespace test2

// ---- test4: Different Weights ------------------------------------------------
namespace test4 {
}  // namespace test4

// ---- test5: Lots of same collisions ------------------------------------------
namespace test5 {
}  // namespace test5

// ---- test8: Hinge stability --------------------------------------------------
namespace test8 {
}  // namespace test8

// ---- test9: Restitution accuracy ---------------------------------------------
namespace test9 {
}  // namespace test9

// ---- test10: Maximum velocity ------------------------------------------------
namespace test10 {
}  // namespace test10

}  // namespace odelab::scene

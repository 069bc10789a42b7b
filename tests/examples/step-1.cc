// examples/step-1 on prm/step-1.prm: the hand-assembled solution equals
// PolyFrac::Elasticity's; errors and rates.

// SOURCE_DIR, defined by deal.II's test macro, is tests/examples: the
// program then reads prm/step-1.prm of the source tree.
#define POLYFRAC_SOURCE_DIR SOURCE_DIR "/../.."
#include "../../examples/step-1/step-1.cc"

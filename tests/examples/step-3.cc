// examples/step-3 on prm/step-3.prm: poromechanics with an injected,
// slipping fracture; the plain fixed-stress iteration and the one with
// Anderson acceleration converge in every step, Anderson with fewer
// iterations, both runs agree, the energy residual stays within its bound,
// faces open and slip.

// SOURCE_DIR, defined by deal.II's test macro, is tests/examples: the
// program then reads prm/step-3.prm of the source tree.
#define POLYFRAC_SOURCE_DIR SOURCE_DIR "/../.."
#include "../../examples/step-3/step-3.cc"

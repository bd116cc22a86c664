#pragma once

// The occam layer in one include: channels (`c << x` is `c ! x`, `c >> x` is `c ? x`), PAR,
// PRI PAR, ALT and PRI ALT with input, timer and SKIP guards, TIMER, and compute(mix).

#include "marsokhod/occam_port/alt.hpp"
#include "marsokhod/occam_port/channel.hpp"
#include "marsokhod/occam_port/compute.hpp"
#include "marsokhod/occam_port/par.hpp"
#include "marsokhod/occam_port/timer.hpp"

// The occam layer in one include: channels and their typed ends, PAR, PRI PAR, ALT, TIMER.
#pragma once

// Channels (`c << x` is `c ! x`, `c >> x` is `c ? x`) with typed ends (`c.in()`, `c.out()`),
// PAR, PRI PAR, ALT and PRI ALT (index form, or guards carrying their handlers) with input,
// timer and SKIP guards, TIMER, and compute(mix).

#include "marsokhod/occam_port/alt.hpp"
#include "marsokhod/occam_port/chan_ends.hpp"
#include "marsokhod/occam_port/channel.hpp"
#include "marsokhod/occam_port/compute.hpp"
#include "marsokhod/occam_port/guarded_alt.hpp"
#include "marsokhod/occam_port/par.hpp"
#include "marsokhod/occam_port/timer.hpp"

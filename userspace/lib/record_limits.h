// SPDX-License-Identifier: LGPL-2.1-or-later
// SPDX-FileCopyrightText: 2026 The rdc authors
/*
 * What a trace's records may carry and ask of a replay: the recorder
 * (record.c) writes within these bounds, replay (replay.c) refuses a
 * record beyond them.
 */
#ifndef RDC_RECORD_LIMITS_H
#define RDC_RECORD_LIMITS_H

#include "rdc_priv.h"

#define REC_MAX_VRAM_WRITE (256u << 20)
/* Words a SUBMIT record carries at most (a command is 4097 at most). */
#define REC_SUBMIT_MAX 65536u
/*
 * What one record may ask of the replay, as rdcd bounds a client's wait or
 * step: one simulated minute of the default core clock (a STEP's cycles, a
 * WAIT's budget, the time to an END).  The recorder writes longer steps in
 * pieces of at most this.  And at most REC_MAX_POWER power cycles, each a
 * new chip.  A trace that asks for more is refused (RDC_E_RANGE), naming
 * the record.
 */
#define REC_MAX_CYCLES (60ull * RDC_DEFAULT_CORE_HZ)
#define REC_MAX_POWER  256u

#endif /* RDC_RECORD_LIMITS_H */

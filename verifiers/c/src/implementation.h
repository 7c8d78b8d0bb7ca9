/* What an implementation reports for one vector (plcvec_out), as the judge reads it. */
#ifndef PLCVEC_IMPLEMENTATION_H
#define PLCVEC_IMPLEMENTATION_H

#include "plcvec/plcvec.h"

/* plcvec_out_status(): ran (read the steps), skipped, or failed. */
enum { PLCVEC_RAN = 0, PLCVEC_SKIPPED = 1, PLCVEC_FAILED = 2 };

struct plcvec_out {
    int *results;               /* per reported step */
    size_t *first;              /* per reported step: index of its first cell */
    size_t n_steps, cap_steps;
    plcvec_reported *cells;
    size_t n_cells, cap_cells;
    int status;
    int overflow;               /* out of memory while recording: reported as an error */
    char message[256];
};

/* A function kept out of line (and out of the hot path's way): the path it leaves then needs no
 * saved registers. Only an optimization; compilers without the attribute inline as they like. */
#if defined(__GNUC__) || defined(__clang__)
#define PLCVEC_OUT_OF_LINE __attribute__((noinline, cold))
#else
#define PLCVEC_OUT_OF_LINE
#endif

/* What a report that broke the interface says (a device before any step, an unknown id). */
extern const char plcvec_out_overflow_message[];

/* The cells reported after step s: [*lo, *hi). Inline: the judge asks at every step. */
static inline void plcvec_out_span(const plcvec_out *out, size_t s, size_t *lo, size_t *hi)
{
    *lo = s < out->n_steps ? out->first[s] : out->n_cells;
    *hi = s + 1 < out->n_steps ? out->first[s + 1] : out->n_cells;
}
/* Grow *p (of *cap items of `size` bytes) to hold `need`; 0 when out of memory. Inline: the room
 * is there but for the first vectors, and every device reported asks. */
int plcvec_grow_to(void **p, size_t *cap, size_t need, size_t size);
static inline int plcvec_grow(void **p, size_t *cap, size_t need, size_t size)
{
    return need <= *cap || plcvec_grow_to(p, cap, need, size);
}
/* Free what a plcvec_out owns, leaving it empty (for one embedded in another struct). */
void plcvec_out_release(plcvec_out *out);

#endif

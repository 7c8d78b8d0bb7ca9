/* The roll-up by reading (TEXT.md): built on the inference (infer.c), what a failing run's failures
 * and known failures would need to pass, in the words every plcvec runner prints. A reading is
 * proposed without the `partial` mark only when it explains every failure of the families it
 * touches and breaks no pass there: a bug that only part of a reading's vectors show is never
 * explained away. */
#include <stdlib.h>
#include <string.h>

#include "rollup.h"
#include "table.h"

#define SHOW_IDS 5      /* vector ids under each group of unexplained failures */

static plcvec_declaration_form declaration_form = PLCVEC_DECLARE_C;

void plcvec_rollup_declaration_form(plcvec_declaration_form form)
{
    declaration_form = form;
}

/* A group of the roll-up: its text (a smallest change, or a list of clauses) and its vectors. */
typedef struct group {
    char key[1024];
    size_t n;
    const plcvec_judged **members;
} group;

typedef struct groups {
    group *items;
    size_t n;
    const plcvec_judged **slots;    /* every group's members, each group a slice */
} groups;

/* Which vectors a part of the roll-up takes, and the text that groups them. */
typedef int (*selector)(const plcvec_inference *inf, const plcvec_judged *r);
typedef void (*keyer)(const plcvec_inference *inf, const plcvec_judged *r, char *key, size_t size);

static int is_failing(const plcvec_judged *r)
{
    return r->status == PLCVEC_FAIL || r->status == PLCVEC_ERROR;
}

static int explained_failing(const plcvec_inference *inf, const plcvec_judged *r)
{
    return is_failing(r) && plcvec_explained(inf, r);
}

static int unexplained_failing(const plcvec_inference *inf, const plcvec_judged *r)
{
    return is_failing(r) && !plcvec_explained(inf, r);
}

static int explained_known(const plcvec_inference *inf, const plcvec_judged *r)
{
    return r->status == PLCVEC_XFAIL && plcvec_explained(inf, r);
}

static int unexplained_failing_or_known(const plcvec_inference *inf, const plcvec_judged *r)
{
    return (is_failing(r) || r->status == PLCVEC_XFAIL) && !plcvec_explained(inf, r);
}

/* "ID=alternative, ..." of the smallest change that explains r. */
static void change_key(const plcvec_inference *inf, const plcvec_judged *r, char *key, size_t size)
{
    int change[PLCVEC_INTERPRETATION_COUNT];
    int n = plcvec_smallest_change(inf, r, change);
    size_t len = 0;
    key[0] = '\0';
    for (int q = 0; q < n && len < size; q++)
        len += (size_t)snprintf(key + len, size - len, "%s%s=%s", q ? ", " : "", plcvec_interpretations[change[q]].id,
                                plcvec_interpretations[change[q]].alternatives[inf->choice[change[q]]]);
}

/* The clauses r cites, ", "-joined: the group of an unexplained failure. */
static void clause_key(const plcvec_inference *inf, const plcvec_judged *r, char *key, size_t size)
{
    (void)inf;
    size_t len = 0;
    key[0] = '\0';
    for (size_t c = 0; c < r->v->n_clauses && len < size; c++)
        len += (size_t)snprintf(key + len, size - len, "%s%s", c ? ", " : "", plcvec_clause(r->v, c));
    if (!r->v->n_clauses)
        snprintf(key, size, "(no clauses)");
}

static group *find_group(groups *g, const char *key)
{
    for (size_t i = 0; i < g->n; i++)
        if (strcmp(g->items[i].key, key) == 0)
            return &g->items[i];
    snprintf(g->items[g->n].key, sizeof g->items[g->n].key, "%s", key);
    return &g->items[g->n++];
}

static int group_order(const void *a, const void *b)
{
    const group *x = a, *y = b;
    if (x->n != y->n)
        return x->n > y->n ? -1 : 1;
    return strcmp(x->key, y->key);
}

/* The vectors `select` takes, grouped by their `key`: largest group first, then by the text. */
static int group_by(groups *g, plcvec_judged *judged, size_t n, const plcvec_inference *inf, selector select, keyer key)
{
    g->n = 0;
    g->items = calloc(n + 1, sizeof *g->items);
    g->slots = malloc((n + 1) * sizeof *g->slots);
    if (!g->items || !g->slots)
        return -1;
    char text[1024];
    for (size_t r = 0; r < n; r++)      /* counted first, so that each group gets its slice */
        if (select(inf, &judged[r])) {
            key(inf, &judged[r], text, sizeof text);
            find_group(g, text)->n++;
        }
    size_t used = 0;
    for (size_t i = 0; i < g->n; i++) {
        g->items[i].members = g->slots + used;
        used += g->items[i].n;
        g->items[i].n = 0;
    }
    for (size_t r = 0; r < n; r++)
        if (select(inf, &judged[r])) {
            key(inf, &judged[r], text, sizeof text);
            group *grp = find_group(g, text);
            grp->members[grp->n++] = &judged[r];
        }
    qsort(g->items, g->n, sizeof *g->items, group_order);
    return 0;
}

static void groups_free(groups *g)
{
    free(g->items);
    free(g->slots);
}

static size_t total(const groups *g)
{
    size_t n = 0;
    for (size_t i = 0; i < g->n; i++)
        n += g->items[i].n;
    return n;
}

/* The families (bit f) of a group's vectors. */
static uint32_t families_of(const group *grp)
{
    uint32_t families = 0;
    for (size_t k = 0; k < grp->n; k++)
        families |= UINT32_C(1) << grp->members[k]->v->family;
    return families;
}

/* How many vectors `select` takes of `families`; the families they are of added to *found. */
static size_t count_of(const plcvec_judged *judged, size_t n, const plcvec_inference *inf, selector select,
                       uint32_t families, uint32_t *found)
{
    size_t count = 0;
    for (size_t r = 0; r < n; r++)
        if ((families >> judged[r].v->family & 1) && select(inf, &judged[r]))
            count++, *found |= UINT32_C(1) << judged[r].v->family;
    return count;
}

static int by_family_name(const void *a, const void *b)
{
    return strcmp(plcvec_family_names[*(const int *)a], plcvec_family_names[*(const int *)b]);
}

static void print_families(FILE *log, uint32_t families)
{
    int list[PLCVEC_FAMILY_COUNT], n = 0;
    for (int f = 0; f < PLCVEC_FAMILY_COUNT; f++)
        if (families >> f & 1)
            list[n++] = f;
    qsort(list, (size_t)n, sizeof *list, by_family_name);
    for (int k = 0; k < n; k++)
        fprintf(log, "%s%s", k ? ", " : "", plcvec_family_names[list[k]]);
}

/* One line per group of explained vectors, marked partial when, in a family some vector of the
 * group is of, a vector `others` takes stays unexplained or a vector that passes now would fail:
 * the reading does not account for everything the implementation does there. */
static void change_lines(FILE *log, const groups *g, const plcvec_judged *judged, size_t n, const plcvec_inference *inf,
                         selector others)
{
    for (size_t i = 0; i < g->n; i++) {
        fprintf(log, "    %6zu  %s", g->items[i].n, g->items[i].key);
        uint32_t families = families_of(&g->items[i]), near = 0;
        size_t u = count_of(judged, n, inf, others, families, &near);
        size_t w = count_of(judged, n, inf, plcvec_broken, families, &near);
        if (u || w) {
            fprintf(log, " (partial: %zu not explained, %zu would fail, in ", u, w);
            print_families(log, near);
            fprintf(log, ")");
        }
        fprintf(log, "\n");
    }
}

static int by_interpretation_id(const void *a, const void *b)
{
    return strcmp(plcvec_interpretations[*(const int *)a].id, plcvec_interpretations[*(const int *)b].id);
}

size_t plcvec_declaration_text(char *buf, size_t size, uint64_t which, const uint8_t *choice)
{
    int list[PLCVEC_INTERPRETATION_COUNT], n = 0;
    for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
        if (which >> i & 1)
            list[n++] = i;
    qsort(list, (size_t)n, sizeof *list, by_interpretation_id);
    size_t len = 0;
    if (size)
        buf[0] = '\0';
    for (int k = 0; k < n; k++) {
        int i = list[k];
        size_t room = len < size ? size - len : 0;
        if (declaration_form == PLCVEC_DECLARE_CHOOSE)
            len += (size_t)snprintf(room ? buf + len : NULL, room, "%s--choose %s=%s", k ? " " : "",
                                    plcvec_interpretations[i].id, plcvec_interpretations[i].alternatives[choice[i]]);
        else
            len += (size_t)snprintf(room ? buf + len : NULL, room, "%s{%s, %s}", k ? ", " : "",
                                    plcvec_declarations[i].interpretation, plcvec_declarations[i].alternatives[choice[i]]);
    }
    return len;
}

/* `declare:` the inferred alternative of each interpretation of `which` (bit i). */
static void declare_line(FILE *log, uint64_t which, const uint8_t *choice)
{
    char text[4096];
    plcvec_declaration_text(text, sizeof text, which, choice);
    fprintf(log, "    declare: %s\n", text);
}

/* READINGS: the failing vectors another alternative explains, the declaration, what it would
 * break, and how many vectors of the same families no reading explains or the declaration breaks. */
static int readings_part(FILE *log, plcvec_judged *judged, size_t n, const plcvec_inference *inf, size_t failing)
{
    groups g;
    int rc = group_by(&g, judged, n, inf, explained_failing, change_key);
    if (rc == 0 && g.n) {
        fprintf(log, "READINGS: %zu of %zu failing vectors pass under other alternatives:\n", total(&g), failing);
        change_lines(log, &g, judged, n, inf, unexplained_failing);
        uint64_t changed = 0;
        for (int i = 0; i < PLCVEC_INTERPRETATION_COUNT; i++)
            changed |= (uint64_t)(inf->choice[i] != inf->followed[i]) << i;
        declare_line(log, changed, inf->choice);
        if (inf->broken)
            fprintf(log, "    (so declared, %zu vectors that pass now would fail)\n", inf->broken);
        uint32_t families = 0, near = 0;
        for (size_t i = 0; i < g.n; i++)
            families |= families_of(&g.items[i]);
        size_t p = count_of(judged, n, inf, unexplained_failing, families, &near);
        size_t q = count_of(judged, n, inf, plcvec_broken, families, &near);
        if (p || q)
            fprintf(log, "    partial: %zu vectors no reading explains and %zu vectors that pass now are of the same "
                         "families; the declaration may hide part of a bug there\n", p, q);
    }
    groups_free(&g);
    return rc;
}

static int id_order(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* NOT EXPLAINED: the failing vectors no offered reading explains, by the clauses they cite. */
static int unexplained_part(FILE *log, plcvec_judged *judged, size_t n, const plcvec_inference *inf)
{
    groups g;
    int rc = group_by(&g, judged, n, inf, unexplained_failing, clause_key);
    if (rc == 0 && g.n) {
        fprintf(log, "NOT EXPLAINED by any reading: %zu failing vectors, by the clauses they cite:\n", total(&g));
        for (size_t i = 0; i < g.n; i++) {
            group *grp = &g.items[i];
            fprintf(log, "    %6zu  %s\n", grp->n, grp->key);
            const char **ids = malloc(grp->n * sizeof *ids);
            for (size_t k = 0; ids && k < grp->n; k++)
                ids[k] = grp->members[k]->v->id;
            if (ids)
                qsort(ids, grp->n, sizeof *ids, id_order);
            for (size_t k = 0; ids && k < grp->n && k < SHOW_IDS; k++)
                fprintf(log, "            %s\n", ids[k]);
            if (grp->n > SHOW_IDS)
                fprintf(log, "            ... and %zu more\n", grp->n - SHOW_IDS);
            free(ids);
        }
    }
    groups_free(&g);
    return rc;
}

/* "known.toml", the files the explained known failures are listed in (in code: "the list in code"). */
static void print_known_files(FILE *log, const groups *g, const plcvec_known_failure *known, size_t n_known)
{
    const char *seen[16];
    size_t n_seen = 0;
    for (size_t i = 0; i < g->n; i++)
        for (size_t k = 0; k < g->items[i].n; k++)
            for (size_t e = 0; e < n_known; e++) {
                if (!known[e].id || strcmp(known[e].id, g->items[i].members[k]->v->id) != 0)
                    continue;
                const char *file = known[e].file ? known[e].file : "the list in code";
                size_t s = 0;
                while (s < n_seen && strcmp(seen[s], file) != 0)
                    s++;
                if (s == n_seen && n_seen < 16) {
                    fprintf(log, "%s%s", n_seen ? ", " : "", file);
                    seen[n_seen++] = file;
                }
                break;
            }
}

/* KNOWN FAILURES: the known failures another alternative explains, the declaration that replaces
 * them, and the file to remove them from. */
static int known_part(FILE *log, plcvec_judged *judged, size_t n, const plcvec_inference *inf,
                      const plcvec_known_failure *known, size_t n_known)
{
    groups g;
    int rc = group_by(&g, judged, n, inf, explained_known, change_key);
    if (rc == 0 && g.n) {
        size_t all = 0;
        uint64_t changed = 0;
        for (size_t r = 0; r < n; r++) {
            all += judged[r].status == PLCVEC_XFAIL;
            int change[PLCVEC_INTERPRETATION_COUNT];
            for (int q = explained_known(inf, &judged[r]) ? plcvec_smallest_change(inf, &judged[r], change) : 0; q > 0; q--)
                changed |= UINT64_C(1) << change[q - 1];
        }
        fprintf(log, "KNOWN FAILURES: %zu of %zu known failures pass under other alternatives:\n", total(&g), all);
        change_lines(log, &g, judged, n, inf, unexplained_failing_or_known);
        declare_line(log, changed, inf->choice);
        fprintf(log, "    then remove those %zu known failures from ", total(&g));
        print_known_files(log, &g, known, n_known);
        fprintf(log, "\n");
    }
    groups_free(&g);
    return rc;
}

int plcvec_rollup_lines(FILE *log, plcvec_judged *judged, size_t n, const uint8_t *followed,
                        const plcvec_known_failure *known, size_t n_known)
{
    size_t failing = 0, xfail = 0;
    for (size_t r = 0; r < n; r++)
        failing += is_failing(&judged[r]), xfail += judged[r].status == PLCVEC_XFAIL;
    if (!failing && !xfail)
        return 0;
    plcvec_inference inf;
    if (plcvec_infer(judged, n, followed, &inf) != 0)
        return -1;
    if (readings_part(log, judged, n, &inf, failing) != 0 || unexplained_part(log, judged, n, &inf) != 0 ||
        known_part(log, judged, n, &inf, known, n_known) != 0)
        return -1;
    return 0;
}

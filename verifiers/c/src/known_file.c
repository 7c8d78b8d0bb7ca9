/* The known-failures file (CONTRACT.md, "The expectations file"), read and written as every
 * plcvec runner reads and writes it (what a listed vector's verdict becomes is known.c's):
 *
 *     [[known-failure]]
 *     id = "fx5-date-compare/LDDT</nonexistent/2024-2-30/s1/vs-previous"
 *     reason = "our calendar check rejects 2008/02/31 (issue #12)"
 *
 * Debian packages no TOML library for C, and the library depends on libc alone, so this is a
 * small strict parser for exactly that format: comments, blank lines, [[known-failure]] headers
 * and `key = "string"` lines (basic strings with TOML's escapes, or 'literal' strings). Anything
 * else is refused with FILE:LINE, never guessed at. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "plcvec/plcvec.h"

#define SECTION "known-failure"

typedef struct parser {
    const char *path;
    int line;
    char *err;
    size_t errlen;
} parser;

static int fail(parser *p, const char *fmt, const char *arg)
{
    char what[400];
    snprintf(what, sizeof what, fmt, arg ? arg : "");
    snprintf(p->err, p->errlen, "%s:%d: %.400s", p->path, p->line, what);
    return -1;
}

static const char *skip_ws(const char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    return s;
}

/* The rest of a line after a value: blanks and an optional comment. */
static int line_end(parser *p, const char *s)
{
    s = skip_ws(s);
    if (*s && *s != '#')
        return fail(p, "not valid TOML: unexpected text after the value", NULL);
    return 0;
}

static int utf8_ok(const unsigned char *s, size_t n, size_t *bad)
{
    for (size_t i = 0; i < n;) {
        unsigned c = s[i];
        size_t len = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        if (!len || i + len > n || (len == 2 && c < 0xC2) || (len == 4 && c > 0xF4)) {
            *bad = i;
            return 0;
        }
        for (size_t k = 1; k < len; k++)
            if ((s[i + k] & 0xC0) != 0x80) {
                *bad = i;
                return 0;
            }
        i += len;
    }
    return 1;
}

static void put_utf8(char **o, unsigned long cp)
{
    char *q = *o;
    if (cp < 0x80)
        *q++ = (char)cp;
    else if (cp < 0x800)
        *q++ = (char)(0xC0 | cp >> 6), *q++ = (char)(0x80 | (cp & 0x3F));
    else if (cp < 0x10000)
        *q++ = (char)(0xE0 | cp >> 12), *q++ = (char)(0x80 | (cp >> 6 & 0x3F)), *q++ = (char)(0x80 | (cp & 0x3F));
    else
        *q++ = (char)(0xF0 | cp >> 18), *q++ = (char)(0x80 | (cp >> 12 & 0x3F)), *q++ = (char)(0x80 | (cp >> 6 & 0x3F)),
        *q++ = (char)(0x80 | (cp & 0x3F));
    *o = q;
}

/* A string value at s (on one line): a malloc'd copy in *out, *after past its closing quote. */
static int string_value(parser *p, const char *s, char **out, const char **after)
{
    char quote = *s;
    if (quote != '"' && quote != '\'')
        return fail(p, "not valid TOML here: `id` and `reason` are strings (\"...\")", NULL);
    if (s[1] == quote && s[2] == quote)
        return fail(p, "multi-line strings are not used in an expectations file; write the value on one line", NULL);
    char *o = malloc(strlen(s) + 1), *start = o;
    if (!o)
        return fail(p, "out of memory", NULL);
    for (s++; *s != quote; s++) {
        unsigned char c = (unsigned char)*s;
        if (!c) {
            free(start);
            return fail(p, "not valid TOML: the string is not closed on its line", NULL);
        }
        if ((c < 0x20 && c != '\t') || c == 0x7F) {
            free(start);
            return fail(p, "not valid TOML: a control character inside a string", NULL);
        }
        if (quote == '\'' || c != '\\') {
            *o++ = (char)c;
            continue;
        }
        char e = *++s;
        const char *simple = strchr("btnfr\"\\", e);
        if (e && simple) {
            static const char to[] = "\b\t\n\f\r\"\\";
            *o++ = to[simple - "btnfr\"\\"];
            continue;
        }
        int digits = e == 'u' ? 4 : e == 'U' ? 8 : 0;
        unsigned long cp = 0;
        for (int k = 1; k <= digits; k++) {
            char h = s[k];
            int v = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : -1;
            if (v < 0) {
                digits = -1;
                break;
            }
            cp = cp * 16 + (unsigned long)v;
        }
        if (digits <= 0 || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) {
            free(start);
            return fail(p, "not valid TOML: an unknown escape in a string", NULL);
        }
        put_utf8(&o, cp);
        s += digits;
    }
    *o = '\0';
    *out = start;
    *after = s + 1;
    return 0;
}

typedef struct entry {
    char *id, *reason;
    int line;
} entry;

/* A finished entry into the list (which takes its strings; each entry holds its own copy of the
 * file's name, so that any entry can be freed alone). */
static int keep(parser *p, entry *e, plcvec_known_failure **list, size_t *n, size_t *cap)
{
    if (*n == *cap) {
        size_t c = *cap ? *cap * 2 : 8;
        plcvec_known_failure *grown = realloc(*list, c * sizeof *grown);
        if (!grown)
            return fail(p, "out of memory", NULL);
        *list = grown;
        *cap = c;
    }
    size_t len = strlen(p->path);
    char *file = malloc(len + 1);
    if (!file)
        return fail(p, "out of memory", NULL);
    memcpy(file, p->path, len + 1);
    (*list)[*n] = (plcvec_known_failure){e->id, e->reason, file, e->line};
    (*n)++;
    e->id = e->reason = NULL;
    return 0;
}

void plcvec_known_free(plcvec_known_failure *list, size_t n)
{
    if (!list)
        return;
    for (size_t i = 0; i < n; i++) {
        free((char *)list[i].id);
        free((char *)list[i].reason);
        free((char *)list[i].file);
    }
    free(list);
}

/* The reason without the blanks around it, in place (as every runner shows it). */
static void trim(char *s)
{
    size_t start = (size_t)(skip_ws(s) - s), len = strlen(s);
    while (len > start && (s[len - 1] == ' ' || s[len - 1] == '\t'))
        len--;
    memmove(s, s + start, len - start);
    s[len - start] = '\0';
}

static int finish(parser *p, entry *e, const plcvec_known_failure *list, size_t n)
{
    p->line = e->line;
    if (!e->id || !*e->id)
        return fail(p, "entry without an `id`", NULL);
    if (e->reason)
        trim(e->reason);
    if (!e->reason || !*e->reason) {
        char what[300];
        snprintf(what, sizeof what, "%.200s: every known failure needs a `reason`", e->id);
        return fail(p, "%s", what);
    }
    for (size_t i = 0; i < n; i++)
        if (strcmp(list[i].id, e->id) == 0) {
            char what[300];
            snprintf(what, sizeof what, "%.200s is listed twice (first at line %d)", e->id, list[i].line);
            return fail(p, "%s", what);
        }
    return 0;
}

/* What the parse has so far: the entries kept, and the entry being read. */
typedef struct reading {
    plcvec_known_failure *list;
    size_t n, cap;
    entry e;
    int in_entry;
} reading;

/* `[[known-failure]]` at s: the entry before it is finished and kept, a new one begins. */
static int header_line(parser *p, reading *r, const char *s)
{
    const char *q = s[1] == '[' ? skip_ws(s + 2) : NULL;
    size_t k = strlen(SECTION);
    if (!q || strncmp(q, SECTION, k) != 0 || strncmp(skip_ws(q + k), "]]", 2) != 0) {
        char name[80];
        snprintf(name, sizeof name, "%.60s", s);
        return fail(p, "unknown table %s; an expectations file holds only [[" SECTION "]] entries", name);
    }
    if (line_end(p, skip_ws(q + k) + 2) != 0)
        return -1;
    if (r->in_entry) {
        int here = p->line;
        if (finish(p, &r->e, r->list, r->n) != 0)
            return -1;
        p->line = here;
        if (keep(p, &r->e, &r->list, &r->n, &r->cap) != 0)
            return -1;
    }
    r->in_entry = 1;
    r->e.line = p->line;
    return 0;
}

/* `key = "value"` at s, inside an entry: `id` or `reason`, each once. */
static int key_line(parser *p, reading *r, const char *s)
{
    const char *k = s;
    while ((*k >= 'a' && *k <= 'z') || (*k >= 'A' && *k <= 'Z') || (*k >= '0' && *k <= '9') || *k == '_' || *k == '-')
        k++;
    char key[64], what[200];
    snprintf(key, sizeof key, "%.*s", (int)(k - s < 60 ? k - s : 60), s);
    const char *eq = skip_ws(k);
    if (k == s || *eq != '=')
        return fail(p, "not valid TOML: expected `key = \"value\"` or [[" SECTION "]]", NULL);
    if (!r->in_entry) {
        snprintf(what, sizeof what, "unknown key '%s'; an expectations file holds only [[" SECTION "]] entries", key);
        return fail(p, "%s", what);
    }
    char **slot = strcmp(key, "id") == 0 ? &r->e.id : strcmp(key, "reason") == 0 ? &r->e.reason : NULL;
    if (!slot) {
        snprintf(what, sizeof what, "unknown key '%s' (an entry has `id` and `reason`)", key);
        return fail(p, "%s", what);
    }
    if (*slot)
        return fail(p, "not valid TOML: `%s` is given twice in one entry", key);
    const char *after = NULL;
    if (string_value(p, skip_ws(eq + 1), slot, &after) != 0)
        return -1;
    return line_end(p, after);
}

/* The whole file, NUL-terminated, into a malloc'd buffer; NULL when it cannot be read. */
static char *read_all(FILE *f, size_t *len)
{
    size_t cap = 4096;
    char *text = malloc(cap);
    *len = 0;
    for (size_t got; text && (got = fread(text + *len, 1, cap - *len - 1, f)) > 0;) {
        *len += got;
        if (*len + 1 == cap) {
            char *grown = realloc(text, cap *= 2);
            if (!grown)
                free(text);
            text = grown;
        }
    }
    if (text && ferror(f)) {
        free(text);
        text = NULL;
    }
    if (text)
        text[*len] = '\0';
    return text;
}

/* The text of a known-failures file, which must be UTF-8 without a NUL; NULL with err otherwise. */
static char *file_text(parser *p)
{
    if (plcvec_file_check(p->path, p->err, p->errlen) != 0)
        return NULL;        /* a named pipe, a folder, a loop of symbolic links: by name, unopened */
    char why[256];
    FILE *f = plcvec_file_open(p->path, why, sizeof why);
    if (!f) {
        snprintf(p->err, p->errlen, "%s: cannot read the expectations file: %s", p->path, why);
        return NULL;
    }
    size_t len;
    char *text = read_all(f, &len);
    fclose(f);
    if (!text) {
        snprintf(p->err, p->errlen, "%s: cannot read the expectations file", p->path);
        return NULL;
    }
    size_t bad = 0;
    if (!utf8_ok((const unsigned char *)text, len, &bad) || strlen(text) != len) {
        p->line = 1;
        for (size_t i = 0; i < len && i < bad; i++)
            p->line += text[i] == '\n';
        free(text);
        fail(p, "not UTF-8 text (a TOML file is UTF-8)", NULL);
        return NULL;
    }
    return text;
}

int plcvec_known_load(const char *path, plcvec_known_failure **out, size_t *n_out, char *err, size_t errlen)
{
    parser p = {path, 0, err, errlen};
    *out = NULL;
    *n_out = 0;
    char *text = file_text(&p);
    if (!text)
        return -1;
    reading r = {NULL, 0, 0, {NULL, NULL, 0}, 0};
    int rc = 0;
    char *line = text;
    for (p.line = 1; line && rc == 0; p.line++) {
        char *nl = strchr(line, '\n');
        if (nl) {
            *nl = '\0';
            if (nl > line && nl[-1] == '\r')
                nl[-1] = '\0';
        }
        const char *s = skip_ws(line);
        line = nl ? nl + 1 : NULL;
        if (*s && *s != '#')
            rc = *s == '[' ? header_line(&p, &r, s) : key_line(&p, &r, s);
    }
    if (rc == 0 && r.in_entry && (rc = finish(&p, &r.e, r.list, r.n)) == 0)
        rc = keep(&p, &r.e, &r.list, &r.n, &r.cap);
    free(r.e.id);
    free(r.e.reason);
    free(text);
    if (rc) {
        plcvec_known_free(r.list, r.n);
        return -1;
    }
    *out = r.list;
    *n_out = r.n;
    return 0;
}

/* ---- writing: the failures of a run, as a starting list ------------------------------------- */

static void toml_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20 || c == 0x7F)
            fprintf(f, "\\u%04X", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

static int by_id(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int plcvec_known_write(const char *path, const char **ids, size_t n, const char *reason, char *err, size_t errlen)
{
    if (plcvec_file_check(path, err, errlen) != 0)
        return -1;      /* renaming over a named pipe or a folder would not write the file asked for */
    /* Written beside the target and renamed over it: a reader never sees half a file. */
    size_t len = strlen(path);
    char *tmp = malloc(len + 16);
    if (!tmp) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    snprintf(tmp, len + 16, "%s.tmp-plcvec", path);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
        free(tmp);
        return -1;
    }
    if (n > 1)
        qsort(ids, n, sizeof *ids, by_id);
    fputs("# Known failures: each passing entry fails the run as stale, so fix and delete.\n", f);
    for (size_t i = 0; i < n; i++) {
        fputs("\n[[" SECTION "]]\nid = ", f);
        toml_string(f, ids[i]);
        fputs("\nreason = ", f);
        toml_string(f, reason);
        fputc('\n', f);
    }
    int bad = ferror(f);
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: cannot write: %s", path, strerror(errno));
        remove(tmp);
        free(tmp);
        return -1;
    }
    free(tmp);
    return 0;
}

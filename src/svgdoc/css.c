/*
** css.c -- <style> sheets: parsed once into selectors and declarations
** (CSS Syntax 3: comments, strings, blocks; a rule with a selector we do
** not support is dropped whole, as CSS drops an invalid selector list),
** indexed by their rightmost compound's id, class or type, and matched
** right to left against the open elements, each (compound, ancestor)
** pair tried at most once per match (failure memos), so that a
** selector of m compounds costs at most 2 m (depth + 1) steps.
** Selectors: type, *, #id, .class, [a], [a=v], [a~=v], [a|=v], [a^=v],
** [a$=v], [a*=v], :first-child, :root; descendant and child
** combinators; lists.  Dynamic pseudo-classes (:hover...) never match a
** static drawing; the rest (siblings, :last-child, :nth-*, :not...) are
** refused with a warning (a stream decides at the element's start:
** :last-child, :only-child, :nth-last-*, :*-of-type but the first, and
** :empty need what follows).  @media: evaluated for a plain screen;
** @import: a warning.
*/
#include <stdlib.h>
#include <string.h>

#include "svgdoc/css.h"

enum { S_TAG, S_ID, S_CLASS, S_ATTR, S_FIRST, S_ROOT, S_NEVER };

typedef struct css_simple {
  int kind, op;                  /* op of [a op v]: 0 (exists), = ~ | ^ $ * */
  const char *name, *value;
} css_simple;

typedef struct css_compound {
  size_t first, n;               /* its simples */
  int comb;                      /* to the next compound on the left: ' ' or '>' */
} css_compound;

typedef struct css_selector {
  size_t first, n;               /* its compounds, the rightmost first */
  unsigned long spec;            /* (ids, classes, types) in 10 bits each */
  size_t decl, ndecl;            /* its rule's declarations */
  size_t next;                   /* the next in its bucket, + 1 (0: none) */
  unsigned anc[8];               /* Bloom slots its ancestors must fill */
  int nanc;
} css_selector;

typedef struct css_decl {
  int prop, important;
  const char *value;
} css_decl;

/* A bucket: the selectors whose rightmost compound has this key. */
typedef struct css_bucket {
  int kind;                      /* S_ID, S_CLASS, S_TAG */
  const char *key;
  size_t head;                   /* selector + 1 */
} css_bucket;

struct svgdoc_css {
  char **texts;                  /* the sheets' strings (malloc'd) */
  size_t ntexts, texts_room, bytes;
  css_simple *simples;
  size_t nsimples, simples_room;
  css_compound *compounds;
  size_t ncompounds, compounds_room;
  css_selector *sels;
  size_t nsels, sels_room;
  css_decl *decls;
  size_t ndecls, decls_room;
  css_bucket *buckets;
  size_t nbuckets, buckets_room;  /* open addressing, room a power of 2 */
  size_t universal;              /* the selectors without a key, + 1 */
  unsigned *memo;                /* failures: (compound, depth) -> gen */
  unsigned *bloom;               /* the open elements' tags, ids, classes */
  unsigned gen;
  double tests;
  int full_warned, transform_warned;
};

/* ---- growing arrays --------------------------------------------------- */

static void *grow(svgdoc *D, void *a, size_t *room, size_t used, size_t size) {
  if (used == *room) {
    size_t r = *room ? 2 * *room : 64;
    void *p = realloc(a, r * size);
    if (p == NULL) svgdoc_nomem(D);
    *room = r;
    return p;
  }
  return a;
}

static struct svgdoc_css *sheet(svgdoc *D) {
  if (D->css == NULL) {
    D->css = calloc(1, sizeof *D->css);
    if (D->css == NULL) svgdoc_nomem(D);
  }
  return D->css;
}

void svgdoc_css_free(svgdoc *D) {
  struct svgdoc_css *C = D->css;
  size_t k;
  if (C == NULL) return;
  for (k = 0; k < C->ntexts; k++) free(C->texts[k]);
  free(C->texts), free(C->simples), free(C->compounds), free(C->sels);
  free(C->decls), free(C->buckets), free(C->memo), free(C->bloom);
  free(C);
  D->css = NULL;
}

int svgdoc_css_any(const svgdoc *D) { return D->css && D->css->nsels > 0; }

static size_t hash(int kind, const char *s, size_t n);

/* ---- characters --------------------------------------------------------- */

static unsigned char lower(unsigned char c) {
  return c >= 'A' && c <= 'Z' ? (unsigned char)(c - 'A' + 'a') : c;
}
static int hexval(unsigned char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = lower(c);
  return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}
/* CSS Syntax 3 section 4.2: name code points (non-ASCII included). */
static int name_char(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         (c >= '0' && c <= '9') || c == '-' || c == '_' || c >= 0x80;
}
#define space svgdoc_space

/* The parser's state: text t[0 .. n-1] (comments gone), out: where
** decoded names go (room for all of them, NUL-ended). */
typedef struct parser {
  svgdoc *D;
  struct svgdoc_css *C;
  const char *t;
  size_t n, i;
  char *out;
  unsigned long line, col;
  const char *why;               /* why the selector in hand is refused */
} parser;

static void ws(parser *p) {
  while (p->i < p->n && space((unsigned char)p->t[p->i])) p->i++;
}

/* A code point as UTF-8 into *o. */
static void put_utf8(char **o, unsigned long c) {
  unsigned char *u = (unsigned char *)*o;
  if (c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = 0xFFFD;
  if (c < 0x80) *u++ = (unsigned char)c;
  else if (c < 0x800) *u++ = (unsigned char)(0xC0 | c >> 6),
                      *u++ = (unsigned char)(0x80 | (c & 63));
  else if (c < 0x10000) *u++ = (unsigned char)(0xE0 | c >> 12),
                        *u++ = (unsigned char)(0x80 | ((c >> 6) & 63)),
                        *u++ = (unsigned char)(0x80 | (c & 63));
  else *u++ = (unsigned char)(0xF0 | c >> 18),
       *u++ = (unsigned char)(0x80 | ((c >> 12) & 63)),
       *u++ = (unsigned char)(0x80 | ((c >> 6) & 63)),
       *u++ = (unsigned char)(0x80 | (c & 63));
  *o = (char *)u;
}

/* An escape at t[i] == '\\' (Syntax 3 section 4.3.7) into *o: the index
** after it (a backslash before a newline or the end is not one: i). */
static size_t escape(const parser *p, size_t i, char **o) {
  size_t j = i + 1, k;
  unsigned long c = 0;
  if (j >= p->n || p->t[j] == '\n' || p->t[j] == '\r' || p->t[j] == '\f')
    return i;
  for (k = 0; k < 6 && j < p->n && hexval((unsigned char)p->t[j]) >= 0; k++, j++)
    c = 16 * c + (unsigned long)hexval((unsigned char)p->t[j]);
  if (k == 0) {
    *(*o)++ = p->t[j];
    return j + 1;
  }
  if (j < p->n && space((unsigned char)p->t[j])) j++;
  put_utf8(o, c);
  return j;
}

static int name_start(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         c >= 0x80;
}

/* An identifier at p->i (Syntax 3 section 4.3.9), decoded and NUL-ended
** into p->out; NULL if none (fold: lower-cased, for property names and
** keywords). */
static const char *ident(parser *p, int fold) {
  char *o = p->out, *start = p->out;
  size_t i = p->i;
  int dashes = 0;
  if (i < p->n && p->t[i] == '-') {
    *o++ = '-', i++, dashes = 1;
    if (i < p->n && p->t[i] == '-') *o++ = '-', i++, dashes = 2;
  }
  if (dashes < 2) {                    /* then a name-start code point */
    if (i >= p->n) return NULL;
    if (p->t[i] == '\\') {
      size_t j = escape(p, i, &o);
      if (j == i) return NULL;
      i = j;
    } else if (name_start((unsigned char)p->t[i])) {
      *o++ = (char)(fold ? lower((unsigned char)p->t[i]) : p->t[i]), i++;
    } else {
      return NULL;
    }
  }
  for (; i < p->n; i++) {
    unsigned char c = (unsigned char)p->t[i];
    if (c == '\\') {
      size_t j = escape(p, i, &o);
      if (j == i) break;
      i = j - 1;
    } else if (name_char(c)) {
      *o++ = (char)(fold ? lower(c) : c);
    } else {
      break;
    }
  }
  *o++ = '\0';
  p->out = o;
  p->i = i;
  return start;
}

/* A string at p->i (its quote), decoded into p->out; NULL if unclosed. */
static const char *string(parser *p) {
  char q = p->t[p->i], *o = p->out, *start = p->out;
  size_t i = p->i + 1;
  for (; i < p->n && p->t[i] != q; i++) {
    if (p->t[i] == '\n') return NULL;              /* a bad string */
    if (p->t[i] == '\\') {
      size_t j = escape(p, i, &o);
      if (j == i) {                                /* an escaped newline */
        if (i + 1 < p->n) i++;
        continue;
      }
      i = j - 1;
    } else {
      *o++ = p->t[i];
    }
  }
  if (i >= p->n) return NULL;
  *o++ = '\0';
  p->out = o;
  p->i = i + 1;
  return start;
}

/* The end of the block or bracket opened at t[i] ('{', '[' or '('): the
** index after its closing one, or n (Syntax 3: an unclosed block ends with
** the sheet).  Strings inside are skipped; linear in its length. */
static size_t block_end(const parser *p, size_t i) {
  char stack[64];
  size_t depth = 0, lost = 0;     /* lost: nesting beyond the stack */
  for (; i < p->n; i++) {
    char c = p->t[i];
    if (c == '"' || c == '\'') {
      size_t j = i + 1;
      while (j < p->n && p->t[j] != c && p->t[j] != '\n')
        j += p->t[j] == '\\' ? 2 : 1;
      i = j < p->n ? j : p->n - 1;
    } else if (c == '\\') {
      i++;
    } else if (c == '{' || c == '[' || c == '(') {
      char close = c == '{' ? '}' : c == '[' ? ']' : ')';
      if (depth < sizeof stack) stack[depth++] = close;
      else lost++;
    } else if ((c == '}' || c == ']' || c == ')') && depth > 0) {
      if (lost > 0) {
        lost--;
      } else if (c == stack[depth - 1]) {
        if (--depth == 0) return i + 1;
      }
    }
  }
  return p->n;
}

/* From p->i to the first of stops at the top level (outside blocks and
** strings); p->i is left on it (or at n). */
static void until(parser *p, const char *stops) {
  while (p->i < p->n && !strchr(stops, p->t[p->i])) {
    char c = p->t[p->i];
    if (c == '{' || c == '[' || c == '(' || c == '"' || c == '\'') {
      if (c == '"' || c == '\'') {
        size_t j = p->i + 1;
        while (j < p->n && p->t[j] != c && p->t[j] != '\n')
          j += p->t[j] == '\\' ? 2 : 1;
        p->i = j < p->n ? j + 1 : p->n;
      } else {
        p->i = block_end(p, p->i);
      }
    } else {
      p->i += c == '\\' ? 2 : 1;
    }
  }
  if (p->i > p->n) p->i = p->n;
}

static void warn_at(parser *p, const char *msg) {
  svgdoc_warn(p->D, p->line, p->col, msg);
}

/* ---- selectors ---------------------------------------------------------- */

static void add_simple(parser *p, int kind, int op, const char *name,
                       const char *value) {
  struct svgdoc_css *C = p->C;
  css_simple *s;
  C->simples = grow(p->D, C->simples, &C->simples_room, C->nsimples, sizeof *s);
  s = &C->simples[C->nsimples++];
  s->kind = kind, s->op = op, s->name = name, s->value = value;
}

/* Pseudo-classes never true of a static drawing (Selectors 4 section 9). */
static const char *const DYNAMIC[] = {
  "hover", "active", "focus", "focus-visible", "focus-within", "visited",
  "link", "any-link", "target", "target-within", "current", "past",
  "future", "playing", "paused", "local-link", "user-invalid"};

/* One compound at p->i into simples (0 when there is none or it is not
** supported: p->why). counts: ids, classes, types. */
static int compound(parser *p, unsigned long counts[3]) {
  size_t start = p->i, k;
  int any = 0;
  if (p->i < p->n && p->t[p->i] == '*') {
    p->i++, any = 1;
  } else {
    const char *tag = ident(p, 0);
    if (tag) add_simple(p, S_TAG, 0, tag, NULL), counts[2]++, any = 1;
  }
  if (p->i < p->n && p->t[p->i] == '|') {
    p->why = "namespace prefixes are not supported";
    return 0;
  }
  for (k = 0; p->i < p->n; k++) {
    char c = p->t[p->i];
    const char *name;
    if (k >= SVGDOC_MAX_CSS_SIMPLES) {
      p->why = "too many simple selectors in one compound";
      return 0;
    }
    if (c == '#' || c == '.') {
      p->i++;
      if ((name = ident(p, 0)) == NULL) { p->why = "a name expected"; return 0; }
      add_simple(p, c == '#' ? S_ID : S_CLASS, 0, name, NULL);
      counts[c == '#' ? 0 : 1]++;
    } else if (c == '[') {
      int op = 0;
      const char *value = NULL;
      p->i++, ws(p);
      if ((name = ident(p, 0)) == NULL) {
        p->why = "an attribute name expected";
        return 0;
      }
      ws(p);
      if (p->i + 1 < p->n && p->t[p->i] == '|' && p->t[p->i + 1] != '=') {
        p->why = "namespace prefixes are not supported";
        return 0;
      }
      if (p->i < p->n && p->t[p->i] == '=') {
        op = '=', p->i++;
      } else if (p->i + 1 < p->n && strchr("~|^$*", p->t[p->i]) &&
                 p->t[p->i + 1] == '=') {
        op = p->t[p->i], p->i += 2;
      }
      if (op) {
        ws(p);
        if (p->i < p->n && (p->t[p->i] == '"' || p->t[p->i] == '\''))
          value = string(p);
        else
          value = ident(p, 0);
        if (value == NULL) { p->why = "an attribute value expected"; return 0; }
        ws(p);
        if (p->i < p->n && (lower((unsigned char)p->t[p->i]) == 'i' ||
                            lower((unsigned char)p->t[p->i]) == 's')) {
          p->why = "attribute selector flags (i, s) are not supported";
          return 0;
        }
      }
      if (p->i >= p->n || p->t[p->i] != ']') { p->why = "']' expected"; return 0; }
      p->i++;
      add_simple(p, S_ATTR, op, name, value);
      counts[1]++;
    } else if (c == ':') {
      size_t d;
      p->i++;
      if (p->i < p->n && p->t[p->i] == ':') {      /* a pseudo-element */
        p->i++;
        if (ident(p, 1) == NULL) { p->why = "a name expected"; return 0; }
        add_simple(p, S_NEVER, 0, NULL, NULL);
        counts[2]++;
        continue;
      }
      if ((name = ident(p, 1)) == NULL) { p->why = "a name expected"; return 0; }
      if (p->i < p->n && p->t[p->i] == '(') {
        p->why = "functional pseudo-classes (:not(), :nth-child()...) are "
                 "not supported";
        return 0;
      }
      counts[1]++;
      if (strcmp(name, "first-child") == 0) {
        add_simple(p, S_FIRST, 0, NULL, NULL);
      } else if (strcmp(name, "root") == 0) {
        add_simple(p, S_ROOT, 0, NULL, NULL);
      } else if (strcmp(name, "before") == 0 || strcmp(name, "after") == 0 ||
                 strcmp(name, "first-line") == 0 ||
                 strcmp(name, "first-letter") == 0) {
        add_simple(p, S_NEVER, 0, NULL, NULL);     /* CSS 2's pseudo-elements */
        counts[1]--, counts[2]++;
      } else {
        for (d = 0; d < sizeof DYNAMIC / sizeof *DYNAMIC; d++)
          if (strcmp(name, DYNAMIC[d]) == 0) break;
        if (d == sizeof DYNAMIC / sizeof *DYNAMIC) {
          p->why = svgdoc_format(p->D, ":%s is not supported (a stream decides "
                                 "at an element's start; :first-child and "
                                 ":root only)", name);
          return 0;
        }
        add_simple(p, S_NEVER, 0, NULL, NULL);
      }
    } else {
      break;
    }
    any = 1;
  }
  if (!any) p->why = p->i == start ? "a selector expected" : "bad selector";
  return any;
}

/* One selector of a list, from p->i to end, as compounds rightmost first. */
static int selector(parser *p, size_t end, css_selector *s) {
  struct svgdoc_css *C = p->C;
  css_compound parts[SVGDOC_MAX_CSS_COMPOUNDS];
  unsigned long counts[3] = {0, 0, 0};
  size_t np = 0, k, n = p->n;
  p->n = end;                         /* the selector's text only */
  ws(p);
  for (;;) {
    int comb = ' ';
    if (np == SVGDOC_MAX_CSS_COMPOUNDS) {
      p->why = "too many compounds in one selector";
      goto bad;
    }
    parts[np].first = C->nsimples;
    if (!compound(p, counts)) goto bad;
    parts[np].n = C->nsimples - parts[np].first;
    np++;
    if (p->i < p->n && !space((unsigned char)p->t[p->i]) &&
        !strchr(">+~", p->t[p->i])) {
      p->why = "bad selector";
      goto bad;
    }
    ws(p);
    if (p->i >= p->n) break;
    if (strchr(">+~", p->t[p->i])) {
      if (p->t[p->i] != '>') {
        p->why = "sibling combinators (+, ~) are not supported";
        goto bad;
      }
      comb = '>', p->i++, ws(p);
    }
    parts[np - 1].comb = comb;       /* to the compound on its right */
  }
  p->n = n;
  s->first = C->ncompounds, s->n = np;
  for (k = 0; k < np; k++) {          /* rightmost first */
    C->compounds = grow(p->D, C->compounds, &C->compounds_room, C->ncompounds,
                        sizeof *C->compounds);
    C->compounds[C->ncompounds] = parts[np - 1 - k];
    /* the combinator between it and the compound on its left */
    C->compounds[C->ncompounds].comb = k + 1 < np ? parts[np - 2 - k].comb : 0;
    C->ncompounds++;
  }
  for (k = 0; k < 3; k++)
    if (counts[k] > 1023) counts[k] = 1023;
  s->spec = counts[0] << 20 | counts[1] << 10 | counts[2];
  return 1;
bad:
  p->n = n;
  return 0;
}

/* ---- the index ------------------------------------------------------------ */

static size_t hash(int kind, const char *s, size_t n) {
  size_t h = 5381 + (size_t)kind, k;
  for (k = 0; k < n; k++) h = h * 33 + (unsigned char)s[k];
  return h;
}

/* A counting Bloom filter of the open elements' tags, ids and classes (as
** browsers keep one): a selector whose left compounds name a key no open
** element has cannot match, and is not walked. */
#define BLOOM_SIZE 4096

static unsigned bloom_slot(int kind, const char *s, size_t n) {
  return (unsigned)((hash(kind, s, n) * 2654435761u) >> 11) & (BLOOM_SIZE - 1);
}

/* The keys of node e counted in (delta 1) or out (-1). */
static void bloom_node(struct svgdoc_css *C, const svgdoc_css_node *e,
                       int delta) {
  const char *s = e->cls;
  C->bloom[bloom_slot(S_TAG, e->tag, strlen(e->tag))] += (unsigned)delta;
  if (e->id) C->bloom[bloom_slot(S_ID, e->id, strlen(e->id))] += (unsigned)delta;
  while (s && *s) {
    const char *w;
    while (*s && space((unsigned char)*s)) s++;
    for (w = s; *s && !space((unsigned char)*s); s++) {}
    if (s > w) C->bloom[bloom_slot(S_CLASS, w, (size_t)(s - w))] += (unsigned)delta;
  }
}

/* The slots of the keys of selector si's compounds left of the rightmost. */
static void bloom_selector(struct svgdoc_css *C, css_selector *sel) {
  size_t k, j;
  sel->nanc = 0;
  for (k = 1; k < sel->n; k++) {
    const css_compound *c = &C->compounds[sel->first + k];
    for (j = 0; j < c->n && sel->nanc < 8; j++) {
      const css_simple *x = &C->simples[c->first + j];
      if (x->kind == S_TAG || x->kind == S_ID || x->kind == S_CLASS)
        sel->anc[sel->nanc++] = bloom_slot(x->kind, x->name, strlen(x->name));
    }
  }
}

/* The slot of key[0 .. n-1] of this kind (empty when absent). */
static size_t bucket_slot(const struct svgdoc_css *C, int kind,
                          const char *key, size_t n) {
  size_t i = hash(kind, key, n) & (C->buckets_room - 1);
  while (C->buckets[i].key &&
         !(C->buckets[i].kind == kind && strncmp(C->buckets[i].key, key, n) == 0 &&
           C->buckets[i].key[n] == '\0'))
    i = (i + 1) & (C->buckets_room - 1);   /* at most half the slots full */
  return i;
}

static void index_selector(svgdoc *D, struct svgdoc_css *C, size_t si) {
  const css_compound *r = &C->compounds[C->sels[si].first];
  int kind = -1;
  const char *key = NULL;
  size_t k, i;
  for (k = 0; k < r->n; k++) {         /* id, else a class, else the type */
    const css_simple *s = &C->simples[r->first + k];
    if (s->kind == S_ID) { kind = S_ID, key = s->name; break; }
    if (s->kind == S_CLASS && kind != S_CLASS) kind = S_CLASS, key = s->name;
    if (s->kind == S_TAG && kind < 0) kind = S_TAG, key = s->name;
  }
  if (key == NULL) {
    C->sels[si].next = C->universal;
    C->universal = si + 1;
    return;
  }
  if (2 * (C->nbuckets + 1) > C->buckets_room) {
    size_t room = C->buckets_room ? 2 * C->buckets_room : 64;
    css_bucket *old = C->buckets;
    size_t old_room = C->buckets_room;
    C->buckets = calloc(room, sizeof *C->buckets);
    if (C->buckets == NULL) {
      C->buckets = old;
      svgdoc_nomem(D);
    }
    C->buckets_room = room;
    for (k = 0; k < old_room; k++)
      if (old[k].key) C->buckets[bucket_slot(C, old[k].kind, old[k].key,
                               strlen(old[k].key))] = old[k];
    free(old);
  }
  i = bucket_slot(C, kind, key, strlen(key));
  if (C->buckets[i].key == NULL) {
    C->buckets[i].kind = kind, C->buckets[i].key = key, C->buckets[i].head = 0;
    C->nbuckets++;
  }
  C->sels[si].next = C->buckets[i].head;
  C->buckets[i].head = si + 1;
}

/* ---- rules ---------------------------------------------------------------- */

/* The declarations of a block t[b .. e-1] (Syntax 3 section 5.4.5): those
** of the reader's properties; the index of the first, their count. */
static size_t declarations(parser *p, size_t b, size_t e, size_t *first) {
  struct svgdoc_css *C = p->C;
  size_t n = p->n, count = 0;
  *first = C->ndecls;
  p->i = b, p->n = e;
  while (p->i < p->n) {
    const char *name;
    size_t vs, ve;
    int prop, important = 0, shorthand, j;
    ws(p);
    if (p->i >= p->n) break;
    name = ident(p, 1);
    ws(p);
    if (name == NULL || p->i >= p->n || p->t[p->i] != ':') {
      until(p, ";");                   /* a bad declaration: to the next */
      if (p->i < p->n) p->i++;
      continue;
    }
    p->i++;
    vs = p->i;
    until(p, ";");
    ve = p->i;
    if (p->i < p->n) p->i++;
    prop = svgdoc_prop_index(name);
    /* the shorthand: its three longhands where it stands (SVG 2 11.6.3) */
    shorthand = prop < 0 && strcmp(name, "marker") == 0;
    if (shorthand) prop = SVGDOC_MARKER_START;
    if (prop < 0 && strcmp(name, "transform") == 0 && !C->transform_warned) {
      /* it would move what is measured: say that it is not */
      warn_at(p, "style sheet: the CSS transform property is not read (the "
                 "transform attribute is)");
      C->transform_warned = 1;
    }
    if (prop < 0) continue;
    while (ve > vs && space((unsigned char)p->t[ve - 1])) ve--;
    {                                  /* "! important" at the end */
      size_t m = ve;
      if (m >= vs + 9) {
        size_t k;
        for (k = 0; k < 9 && lower((unsigned char)p->t[m - 9 + k]) == "important"[k]; k++) {}
        if (k == 9) {
          size_t q = m - 9;
          while (q > vs && space((unsigned char)p->t[q - 1])) q--;
          if (q > vs && p->t[q - 1] == '!') {
            important = 1;
            ve = q - 1;
            while (ve > vs && space((unsigned char)p->t[ve - 1])) ve--;
          }
        }
      }
    }
    while (vs < ve && space((unsigned char)p->t[vs])) vs++;
    if (vs == ve) continue;            /* an empty value is invalid */
    if (C->ndecls >= SVGDOC_MAX_CSS_DECLS) {
      if (!C->full_warned)
        warn_at(p, svgdoc_format(p->D, "style sheets with more than %d "
                                 "declarations: the rest is ignored",
                                 SVGDOC_MAX_CSS_DECLS));
      C->full_warned = 1;
      break;
    }
    {                                  /* an invalid value is dropped */
      size_t k;
      for (k = 0; k < ve - vs; k++) p->out[k] = (char)lower((unsigned char)p->t[vs + k]);
      p->out[ve - vs] = '\0';
      if (!svgdoc_prop_valid(prop, p->out)) {
        warn_at(p, svgdoc_format(p->D, "style sheet: %s '%s' is not a valid "
                                 "value: ignored", name, p->out));
        continue;
      }
      memcpy(p->out, p->t + vs, ve - vs);  /* kept as written: url(#Id) */
    }
    for (j = 0; j <= (shorthand ? 2 : 0); j++) {
      C->decls = grow(p->D, C->decls, &C->decls_room, C->ndecls, sizeof *C->decls);
      C->decls[C->ndecls].prop = prop + j;
      C->decls[C->ndecls].important = important;
      C->decls[C->ndecls].value = p->out;
      C->ndecls++;
      count++;
    }
    p->out += ve - vs + 1;
  }
  p->n = n;
  return count;
}

/* A style rule: the selector list t[ps .. pe-1], the block at t[b]. */
static void style_rule(parser *p, size_t ps, size_t pe, size_t b) {
  struct svgdoc_css *C = p->C;
  size_t e = block_end(p, b), first, ndecl, s0 = C->nsels, k;
  size_t simples = C->nsimples, compounds = C->ncompounds;
  int ok = 1;
  /* the selectors, split at top-level commas */
  p->i = ps;
  while (ok && p->i < pe) {
    size_t start = p->i, n = p->n;
    css_selector s;
    p->n = pe;
    until(p, ",");
    p->n = n;
    if (C->nsels >= SVGDOC_MAX_CSS_SELECTORS) {
      if (!C->full_warned)
        warn_at(p, svgdoc_format(p->D, "style sheets with more than %d "
                                 "selectors: the rest is ignored",
                                 SVGDOC_MAX_CSS_SELECTORS));
      C->full_warned = 1;
      ok = 0;
      break;
    }
    {
      size_t end = p->i;
      p->i = start;
      p->why = NULL;
      if (!selector(p, end, &s)) {
        size_t len = pe - ps;
        while (len > 0 && space((unsigned char)p->t[ps + len - 1])) len--;
        warn_at(p, svgdoc_format(p->D, "style sheet: rule '%.*s' ignored: %s",
                                 (int)(len > 80 ? 80 : len), p->t + ps,
                                 p->why ? p->why : "bad selector"));
        ok = 0;
        break;
      }
      p->i = end < pe ? end + 1 : pe;
    }
    C->sels = grow(p->D, C->sels, &C->sels_room, C->nsels, sizeof *C->sels);
    C->sels[C->nsels++] = s;
  }
  if (ok && C->nsels > s0) {
    ndecl = declarations(p, b + 1, e > b + 1 && p->t[e - 1] == '}' ? e - 1 : e,
                         &first);
    for (k = s0; k < C->nsels; k++) {
      C->sels[k].decl = first, C->sels[k].ndecl = ndecl;
      bloom_selector(C, &C->sels[k]);
      if (ndecl > 0) index_selector(p->D, C, k);
    }
  }
  if (!ok) {                          /* the whole rule goes */
    C->nsels = s0, C->nsimples = simples, C->ncompounds = compounds;
  }
  p->i = e;
}

/* Does a media query list t[s .. e-1] hold for a plain screen (Media
** Queries 4)?  A query of media types only: all and screen hold, others
** not; "not" inverts; a query with a feature ("(min-width: ...)", "and
** (...)") is taken as false: a reader has no window or preferences. */
static int media_holds(const parser *p, size_t s, size_t e) {
  size_t i = s;
  while (i < e && space((unsigned char)p->t[i])) i++;
  if (i == e) return 1;              /* an empty list: all */
  while (i < e) {
    size_t q = i, qe;
    int neg = 0, holds = -1;
    char word[16];
    while (i < e && p->t[i] != ',') i++;
    qe = i;
    if (i < e) i++;
    while (q < qe) {                 /* its words */
      size_t w = 0;
      while (q < qe && space((unsigned char)p->t[q])) q++;
      if (q == qe) break;
      if (p->t[q] == '(') { holds = 0, neg = 0; break; }
      while (q < qe && !space((unsigned char)p->t[q]) && p->t[q] != '(') {
        if (w + 1 < sizeof word) word[w++] = (char)lower((unsigned char)p->t[q]);
        q++;
      }
      word[w] = '\0';
      if (strcmp(word, "not") == 0 && holds < 0) neg = 1;
      else if (strcmp(word, "only") == 0 && holds < 0) {}
      else if (strcmp(word, "and") == 0) { holds = 0, neg = 0; break; }
      else if (holds < 0)
        holds = strcmp(word, "all") == 0 || strcmp(word, "screen") == 0;
      else { holds = 0, neg = 0; break; }
    }
    if (holds < 0) holds = 0, neg = 0;   /* no media type: not a query */
    if (neg ? !holds : holds) return 1;
  }
  return 0;
}

/* The rules from p->i to the end, or to the '}' that closes an @media
** block (nest > 0). */
static void rules(parser *p, int nest) {
  while (p->i < p->n) {
    char c;
    ws(p);
    if (p->i >= p->n) return;
    c = p->t[p->i];
    if (c == '}') {
      p->i++;
      if (nest > 0) return;
      continue;                       /* a stray '}' */
    }
    if (p->n - p->i >= 4 && memcmp(p->t + p->i, "<!--", 4) == 0) {
      p->i += 4;
      continue;
    }
    if (p->n - p->i >= 3 && memcmp(p->t + p->i, "-->", 3) == 0) {
      p->i += 3;
      continue;
    }
    if (c == '@') {
      const char *name;
      size_t ps;
      p->i++;
      name = ident(p, 1);
      ps = p->i;
      until(p, "{;}");
      if (name && strcmp(name, "import") == 0) {
        warn_at(p, "style sheet: @import is not read (the imported rules "
                   "are left out)");
      }
      if (p->i < p->n && p->t[p->i] == '{') {
        if (name && strcmp(name, "media") == 0 && nest < SVGDOC_MAX_CSS_NESTING &&
            media_holds(p, ps, p->i)) {
          p->i++;
          rules(p, nest + 1);
        } else {
          p->i = block_end(p, p->i);
        }
      } else if (p->i < p->n && p->t[p->i] == ';') {
        p->i++;
      }
      continue;
    }
    {
      size_t ps = p->i;
      until(p, nest > 0 ? "{}" : "{");
      if (p->i >= p->n || p->t[p->i] != '{') continue;   /* no block: dropped */
      style_rule(p, ps, p->i, p->i);
    }
  }
}

void svgdoc_css_add(svgdoc *D, const char *text, size_t n, const char *media,
                    unsigned long line, unsigned long col) {
  struct svgdoc_css *C = sheet(D);
  parser P;
  char *t, *o;
  size_t i;
  if (C->bytes + n > SVGDOC_MAX_CSS_BYTES) {
    svgdoc_warn(D, line, col, svgdoc_format(D, "style sheets longer than "
                    "%lu bytes in all: this one is ignored",
                    (unsigned long)SVGDOC_MAX_CSS_BYTES));
    return;
  }
  C->bytes += n;
  if (media) {                         /* <style media="...">: its own query */
    P.t = media, P.n = strlen(media);
    if (!media_holds(&P, 0, P.n)) return;
  }
  C->texts = grow(D, C->texts, &C->texts_room, C->ntexts, sizeof *C->texts);
  /* the text without comments, then room for every name decoded */
  t = malloc(5 * n + 5);
  if (t == NULL) svgdoc_nomem(D);
  C->texts[C->ntexts++] = t;
  for (i = 0, o = t; i < n;) {
    char c = text[i];
    if (c == '/' && i + 1 < n && text[i + 1] == '*') {
      const char *e = NULL;
      size_t j;
      for (j = i + 2; j + 1 < n; j++)
        if (text[j] == '*' && text[j + 1] == '/') { e = text + j; break; }
      i = e ? (size_t)(e - text) + 2 : n;
      *o++ = ' ';
    } else if (c == '"' || c == '\'') {
      *o++ = c, i++;
      while (i < n && text[i] != c && text[i] != '\n') {
        if (text[i] == '\\' && i + 1 < n) *o++ = text[i++];
        *o++ = text[i++];
      }
      if (i < n) *o++ = text[i++];
    } else {
      *o++ = c == '\0' ? ' ' : c, i++;
    }
  }
  *o++ = '\0';
  P.D = D, P.C = C, P.t = t, P.n = (size_t)(o - 1 - t), P.i = 0;
  P.out = o, P.line = line, P.col = col, P.why = NULL;
  rules(&P, 0);
}

/* ---- matching --------------------------------------------------------------- */

/* Is word w (length wl) one of the whitespace-separated words of s? */
static int has_word(const char *s, const char *w, size_t wl) {
  while (s && *s) {
    const char *e;
    while (*s && space((unsigned char)*s)) s++;
    for (e = s; *e && !space((unsigned char)*e); e++) {}
    if ((size_t)(e - s) == wl && wl > 0 && memcmp(s, w, wl) == 0) return 1;
    s = e;
  }
  return 0;
}

static int attr_matches(const css_simple *s, const char **atts) {
  const char *v = NULL;
  size_t vl, n;
  for (; atts && *atts; atts += 2)
    if (strcmp(atts[0], s->name) == 0) { v = atts[1]; break; }
  if (v == NULL) return 0;
  if (s->op == 0) return 1;
  vl = strlen(v), n = strlen(s->value);
  switch (s->op) {
  case '=': return strcmp(v, s->value) == 0;
  case '~': return has_word(v, s->value, n) && !strpbrk(s->value, " \t\n\r\f");
  case '|': return strncmp(v, s->value, n) == 0 && (v[n] == '\0' || v[n] == '-');
  case '^': return n > 0 && strncmp(v, s->value, n) == 0;
  case '$': return n > 0 && vl >= n && memcmp(v + vl - n, s->value, n) == 0;
  default: return n > 0 && strstr(v, s->value) != NULL;
  }
}

static int compound_matches(svgdoc *D, const css_compound *c, size_t depth,
                            unsigned long line, unsigned long col) {
  struct svgdoc_css *C = D->css;
  const svgdoc_css_node *e = &D->nodes[depth];
  size_t k;
  if (++C->tests > SVGDOC_MAX_CSS_TESTS +
                       SVGDOC_CSS_TESTS_PER_BYTE * (double)D->bytes)
    svgdoc_fail(D, line, col, "style sheet: matching its selectors takes "
                "more than %.0f tests (%.0f and %.0f a byte of the document: "
                "too many selectors for it)", C->tests - 1, SVGDOC_MAX_CSS_TESTS,
                SVGDOC_CSS_TESTS_PER_BYTE);
  for (k = 0; k < c->n; k++) {
    const css_simple *s = &C->simples[c->first + k];
    int ok;
    switch (s->kind) {
    case S_TAG: ok = strcmp(e->tag, s->name) == 0; break;
    case S_ID: ok = e->id && strcmp(e->id, s->name) == 0; break;
    case S_CLASS: ok = has_word(e->cls, s->name, strlen(s->name)); break;
    case S_ATTR: ok = attr_matches(s, e->atts); break;
    case S_FIRST: ok = e->first_child; break;
    case S_ROOT: ok = depth == 0; break;
    default: ok = 0;
    }
    if (!ok) return 0;
  }
  return 1;
}

/* The failure memos of compound i at node depth: fail[0]: compound i
** there and the compounds left of it do not match; fail[1]: nor at any
** ancestor of depth (inclusive).  Each pair is computed once per match,
** so a selector of m compounds costs at most 2 m (depth + 1) steps. */
static unsigned *memo(const svgdoc *D, int which, size_t i, size_t depth) {
  size_t row = (size_t)D->o.max_depth + 2;
  return &D->css->memo[(which * SVGDOC_MAX_CSS_COMPOUNDS + i) * row + depth];
}

static int match_below(svgdoc *D, const css_selector *s, size_t i,
                       size_t depth, unsigned long line, unsigned long col);

/* Does compound i of selector s match node depth, and the compounds left
** of it its ancestors? */
static int match_at(svgdoc *D, const css_selector *s, size_t i, size_t depth,
                    unsigned long line, unsigned long col) {
  struct svgdoc_css *C = D->css;
  const css_compound *c = &C->compounds[s->first + i];
  unsigned *fail = memo(D, 0, i, depth);
  if (*fail == C->gen) return 0;
  if (compound_matches(D, c, depth, line, col)) {
    if (i + 1 == s->n) return 1;
    if (depth > 0 && (c->comb == '>'
                          ? match_at(D, s, i + 1, depth - 1, line, col)
                          : match_below(D, s, i + 1, depth - 1, line, col)))
      return 1;
  }
  *fail = C->gen;
  return 0;
}

/* Does compound i (and what is left of it) match node depth or one of its
** ancestors?  A success is the whole selector's; a failure is remembered
** for every node walked, down to one known to fail. */
static int match_below(svgdoc *D, const css_selector *s, size_t i,
                       size_t depth, unsigned long line, unsigned long col) {
  struct svgdoc_css *C = D->css;
  size_t a = depth, stop;
  for (;;) {
    if (*memo(D, 1, i, a) == C->gen) break;
    if (match_at(D, s, i, a, line, col)) return 1;
    if (a == 0) break;
    a--;
  }
  stop = a;
  for (a = depth; a > stop; a--) *memo(D, 1, i, a) = C->gen;
  *memo(D, 1, i, stop) = C->gen;
  return 0;
}

/* The chain of selectors from head (+ 1) into m, those that match. */
static void try_chain(svgdoc *D, size_t head, size_t depth, unsigned long line,
                      unsigned long col, unsigned long best[2][SVGDOC_NPROPS],
                      size_t order[2][SVGDOC_NPROPS], svgdoc_css_match *m) {
  struct svgdoc_css *C = D->css;
  for (; head; head = C->sels[head - 1].next) {
    const css_selector *s = &C->sels[head - 1];
    size_t k;
    int j;
    for (j = 0; j < s->nanc && C->bloom[s->anc[j]] > 0; j++) {}
    if (j < s->nanc) continue;         /* an ancestor key no open element has */
    if (++C->gen == 0) {               /* wrapped: the memo starts afresh */
      memset(C->memo, 0, 2 * SVGDOC_MAX_CSS_COMPOUNDS *
             ((size_t)D->o.max_depth + 2) * sizeof *C->memo);
      C->gen = 1;
    }
    if (!match_at(D, s, 0, depth, line, col)) continue;
    for (k = 0; k < s->ndecl; k++) {
      const css_decl *d = &C->decls[s->decl + k];
      size_t o = s->decl + k + 1;
      int im = d->important;
      /* specificity, then the order in the sheets (Cascade 4 section 6.4) */
      if (s->spec > best[im][d->prop] ||
          (s->spec == best[im][d->prop] && o > order[im][d->prop])) {
        best[im][d->prop] = s->spec, order[im][d->prop] = o;
        if (im) m->important[d->prop] = d->value;
        else m->normal[d->prop] = d->value;
      }
    }
  }
}

/* The selectors keyed by key[0 .. n-1] of this kind, + 1 (0: none). */
static size_t chain_of(const struct svgdoc_css *C, int kind, const char *key,
                       size_t n) {
  size_t i;
  if (C->buckets_room == 0 || key == NULL) return 0;
  i = bucket_slot(C, kind, key, n);
  return C->buckets[i].key ? C->buckets[i].head : 0;
}

void svgdoc_css_match_node(svgdoc *D, size_t depth, unsigned long line,
                           unsigned long col, svgdoc_css_match *m) {
  struct svgdoc_css *C = D->css;
  const svgdoc_css_node *e = &D->nodes[depth];
  unsigned long best[2][SVGDOC_NPROPS];
  size_t order[2][SVGDOC_NPROPS];
  memset(m, 0, sizeof *m);
  if (!svgdoc_css_any(D)) return;
  memset(best, 0, sizeof best), memset(order, 0, sizeof order);
  if (C->memo == NULL) {
    C->memo = calloc(2 * SVGDOC_MAX_CSS_COMPOUNDS *
                     ((size_t)D->o.max_depth + 2), sizeof *C->memo);
    if (C->memo == NULL) svgdoc_nomem(D);
  }
  try_chain(D, C->universal, depth, line, col, best, order, m);
  try_chain(D, chain_of(C, S_TAG, e->tag, strlen(e->tag)), depth, line, col, best, order, m);
  if (e->id)
    try_chain(D, chain_of(C, S_ID, e->id, strlen(e->id)), depth, line, col,
              best, order, m);
  if (e->cls) {                       /* each word (a repeated one again) */
    const char *s = e->cls;
    size_t words = 0;
    while (*s) {
      const char *w;
      while (*s && space((unsigned char)*s)) s++;
      for (w = s; *s && !space((unsigned char)*s); s++) {}
      if (s == w) continue;
      if (++words > 256) break;        /* a class list's words: capped */
      try_chain(D, chain_of(C, S_CLASS, w, (size_t)(s - w)), depth, line, col,
                best, order, m);
    }
  }
}

/* ---- the nodes and the kept declarations ---------------------------------- */

void svgdoc_css_open(svgdoc *D, size_t depth, const char *tag,
                     const char **atts) {
  svgdoc_css_node *e = &D->nodes[depth];
  size_t n = 0, k, size = strlen(tag) + 1;
  const char **a;
  char *at;
  for (n = 0; atts[n]; n += 2) size += strlen(atts[n]) + strlen(atts[n + 1]) + 2;
  a = svgdoc_alloc(D, (n + 1) * sizeof *a + size);
  at = (char *)(a + n + 1);
  for (k = 0; k < n; k++) {
    size_t l = strlen(atts[k]) + 1;
    a[k] = memcpy(at, atts[k], l);
    at += l;
  }
  a[n] = NULL;
  e->tag = memcpy(at, tag, strlen(tag) + 1);
  e->atts = a;
  e->id = svgdoc_attr(a, "id");
  e->cls = svgdoc_attr(a, "class");
  e->children = 0;
  e->first_child = depth == 0 || D->nodes[depth - 1].children == 0;
  if (depth > 0) D->nodes[depth - 1].children++;
  if (sheet(D)->bloom == NULL) {
    D->css->bloom = calloc(BLOOM_SIZE, sizeof *D->css->bloom);
    if (D->css->bloom == NULL) svgdoc_nomem(D);
  }
  bloom_node(D->css, e, 1);
}

void svgdoc_css_close(svgdoc *D, size_t depth) {
  if (D->css && D->css->bloom) bloom_node(D->css, &D->nodes[depth], -1);
}

size_t svgdoc_css_store(svgdoc *D, const svgdoc_css_match *m, const char **a,
                        size_t n) {
  int k;
  for (k = 0; k < SVGDOC_NPROPS; k++) {
    if (m->normal[k]) {
      a[n++] = svgdoc_format(D, "\1n:%s", svgdoc_prop_name(k));
      a[n++] = m->normal[k];
    }
    if (m->important[k]) {
      a[n++] = svgdoc_format(D, "\1i:%s", svgdoc_prop_name(k));
      a[n++] = m->important[k];
    }
  }
  a[n] = NULL;
  return n;
}

void svgdoc_css_for(svgdoc *D, const char **atts, int live, size_t depth,
                    unsigned long line, unsigned long col,
                    svgdoc_css_match *m) {
  const char **a;
  int kept = 0;
  memset(m, 0, sizeof *m);
  for (a = atts; *a; a += 2) {
    if (a[0][0] == '\1' && a[0][2] == ':') {
      int k = svgdoc_prop_index(a[0] + 3);
      kept = 1;
      if (k < 0) continue;
      if (a[0][1] == 'i') m->important[k] = a[1];
      else m->normal[k] = a[1];
    }
  }
  if (!kept && live) svgdoc_css_match_node(D, depth, line, col, m);
}

/* ---- <style> elements ------------------------------------------------------- */

/* A <style> of type text/css (the default, SVG 2 section 6.4) starts at
** depth: its text is gathered until it ends. */
void svgdoc_css_style_start(svgdoc *D, const char **atts, size_t depth,
                            unsigned long line, unsigned long col) {
  const char *type = svgdoc_attr(atts, "type"), *media;
  if (type && !svgdoc_blank(type)) {
    const char *s = type, *e;
    while (space((unsigned char)*s)) s++;
    for (e = s + strlen(s); e > s && space((unsigned char)e[-1]); e--) {}
    if (!((size_t)(e - s) == 8 && strncmp(s, "text/css", 8) == 0)) return;
  }
  D->style_depth = depth + 1;
  D->shapes_before = D->shapes_seen;
  D->style_line = line, D->style_col = col;
  D->style_text.len = 0;
  D->style_media.len = 0;
  D->style_has_media = 0;
  if ((media = svgdoc_attr(atts, "media")) != NULL) {
    svgdoc_append(D, &D->style_media, media, strlen(media) + 1);
    D->style_has_media = 1;
  }
}

void svgdoc_css_text(svgdoc *D, const char *s, size_t n) {
  size_t had = D->css ? D->css->bytes : 0;
  if (D->style_depth == 0) return;
  /* beyond the cap, one byte more says so */
  if (had + D->style_text.len + n > SVGDOC_MAX_CSS_BYTES)
    n = had + D->style_text.len > SVGDOC_MAX_CSS_BYTES ? 0 : 1 +
        SVGDOC_MAX_CSS_BYTES - had - D->style_text.len;
  if (n > 0) svgdoc_append(D, &D->style_text, s, n);
}

void svgdoc_css_style_end(svgdoc *D, size_t depth) {
  if (D->style_depth != depth + 1) return;
  D->style_depth = 0;
  svgdoc_append(D, &D->style_text, "", 1);   /* NUL-ended */
  D->style_text.len--;
  if (D->shapes_before > 0 && !svgdoc_blank(D->style_text.s))
    svgdoc_warn(D, D->style_line, D->style_col, svgdoc_format(D, "style sheet "
                "after %lu shapes or uses: it applies only to the elements that "
                "start after it (the stream)", (unsigned long)D->shapes_before));
  svgdoc_css_add(D, D->style_text.s, D->style_text.len,
                 D->style_has_media ? D->style_media.s : NULL, D->style_line,
                 D->style_col);
}

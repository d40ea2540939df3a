/*
** memory.c -- what a document keeps lives in its pools: D->keep (what
** <use> can still reference, freed with the document) and D->tmp, a stack
** given back as the elements that took from it end (svgdoc_mark_get,
** svgdoc_release), so that a stream's memory does not grow with it.  A
** located error is a message, a place and a jump back to the expat
** callback that started the work (svgdoc_fail; never across expat's own
** frames).  Warnings are kept here too (svgdoc_warn), for every file of
** the area.
*/
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "svgdoc/internal.h"

#define POOL_BLOCK 65536

struct svgdoc_block {
  svgdoc_block *next;
  size_t size;
};

void *svgdoc_alloc(svgdoc *D, size_t n) {
  svgdoc_arena *A = D->arena;
  void *p;
  n = (n + 15) & ~(size_t)15;
  if (n > A->left) {
    size_t size = n > POOL_BLOCK / 2 ? n : POOL_BLOCK;
    svgdoc_block *b;
    if (size == POOL_BLOCK && D->spare) {      /* a tmp block given back */
      b = D->spare;
      D->spare = NULL;
    } else {
      b = malloc(sizeof(svgdoc_block) + 16 + size);
      if (b == NULL) svgdoc_nomem(D);
      b->size = size;
    }
    b->next = A->blocks;
    A->blocks = b;
    A->at = (char *)(b + 1) + 16 - ((size_t)(b + 1) & 15);
    A->left = size;
  }
  p = A->at;
  A->at += n;
  A->left -= n;
  return p;
}

void svgdoc_mark_get(const svgdoc *D, svgdoc_mark *m) { *m = D->tmp; }

void svgdoc_release(svgdoc *D, const svgdoc_mark *m) {
  while (D->tmp.blocks != m->blocks && D->tmp.blocks) {  /* the newer blocks */
    svgdoc_block *b = D->tmp.blocks;
    D->tmp.blocks = b->next;
    if (D->spare == NULL && b->size == POOL_BLOCK) D->spare = b;
    else free(b);
  }
  D->tmp = *m;
}

char *svgdoc_strdup(svgdoc *D, const char *s, size_t n) {
  char *p = svgdoc_alloc(D, n + 1);
  memcpy(p, s, n);
  p[n] = '\0';
  return p;
}

static char *vformat(const char *fmt, va_list ap) {
  va_list aq;
  int n;
  char *p;
  va_copy(aq, ap);
  n = vsnprintf(NULL, 0, fmt, aq);
  va_end(aq);
  if (n < 0 || (p = malloc((size_t)n + 1)) == NULL) return NULL;
  vsnprintf(p, (size_t)n + 1, fmt, ap);
  return p;
}

char *svgdoc_message(const char *fmt, ...) {
  va_list ap;
  char *p;
  va_start(ap, fmt);
  p = vformat(fmt, ap);
  va_end(ap);
  return p;
}

char *svgdoc_format(svgdoc *D, const char *fmt, ...) {
  va_list ap;
  int n;
  char *p;
  va_start(ap, fmt);
  n = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  if (n < 0) svgdoc_nomem(D);
  p = svgdoc_alloc(D, (size_t)n + 1);
  va_start(ap, fmt);
  vsnprintf(p, (size_t)n + 1, fmt, ap);
  va_end(ap);
  return p;
}

void svgdoc_set_error(svgdoc *D, unsigned long line, unsigned long col,
                      char *msg) {
  D->failed = 1;
  D->err_line = line, D->err_col = col;
  D->err_msg = msg;
}

void svgdoc_fail(svgdoc *D, unsigned long line, unsigned long col,
                 const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  svgdoc_set_error(D, line, col, vformat(fmt, ap));
  va_end(ap);
  longjmp(*D->on_error, 1);
}

void svgdoc_nomem(svgdoc *D) {
  svgdoc_set_error(D, 0, 0, NULL);         /* NULL: "not enough memory" */
  longjmp(*D->on_error, 1);
}

void svgdoc_reserve(svgdoc *D, svgdoc_buffer *b, size_t n) {
  if (n > b->room) {
    size_t room = b->room ? b->room : 64;
    char *s;
    while (room < n) room *= 2;
    s = realloc(b->s, room);
    if (s == NULL) svgdoc_nomem(D);
    b->s = s, b->room = room;
  }
}

void svgdoc_append(svgdoc *D, svgdoc_buffer *b, const char *s, size_t n) {
  svgdoc_reserve(D, b, b->len + n + 1);
  memcpy(b->s + b->len, s, n);
  b->len += n;
  b->s[b->len] = '\0';
}

static void free_blocks(svgdoc_block *b) {
  while (b) {
    svgdoc_block *next = b->next;
    free(b);
    b = next;
  }
}

void svgdoc_free_pool(svgdoc *D) {
  free_blocks(D->keep.blocks);
  free_blocks(D->tmp.blocks);
  free(D->spare);
  D->keep.blocks = D->tmp.blocks = D->spare = NULL;
}

/* An error a renderer passes over (a missing reference, bad path data, a
** negative radius): a warning "what; consequence" and the reading goes on,
** or under o.strict the error "what". */
void svgdoc_lenient(svgdoc *D, unsigned long line, unsigned long col,
                    const char *what, const char *consequence) {
  if (D->o.strict) svgdoc_fail(D, line, col, "%s", what);
  svgdoc_warn(D, line, col, svgdoc_format(D, "%s; %s", what, consequence));
}

/* A warning, its message copied into the document's own pool (msg may
** be in the open element's); under o.strict, an error. */
void svgdoc_warn(svgdoc *D, unsigned long line, unsigned long col,
                 const char *msg) {
  svgdoc_warning *w;
  svgdoc_arena *was = D->arena;
  if (D->o.strict) svgdoc_fail(D, line, col, "%s", msg);
  if (D->nwarnings >= SVGDOC_MAX_WARNINGS) return;
  if (D->warnings == NULL) {
    D->warnings = malloc(SVGDOC_MAX_WARNINGS * sizeof *D->warnings);
    if (D->warnings == NULL) svgdoc_nomem(D);
  }
  D->arena = &D->keep;
  msg = svgdoc_strdup(D, msg, strlen(msg));
  D->arena = was;
  w = &D->warnings[D->nwarnings++];
  w->line = line, w->col = col, w->msg = msg;
}

/* hol_alloc.h - the allocator hooks shared by core and render.
 *
 * Contract
 * - A module that allocates takes a hol_alloc in its desc and makes every
 *   allocation through it, once, at create/make time. Both hooks set, or
 *   neither (then malloc and free).
 * - hol_alloc_mem / hol_alloc_release apply that rule; a NULL hol_alloc is
 *   the default.
 */
#ifndef HOL_ALLOC_H
#define HOL_ALLOC_H

#include <stddef.h>
#include <stdlib.h>

typedef struct hol_alloc {
    void *(*alloc)(size_t size, void *user); /* NULL: malloc */
    void (*free)(void *ptr, void *user);     /* NULL: free */
    void *user;
} hol_alloc;

static inline void *hol_alloc_mem(const hol_alloc *a, size_t size)
{
    return a && a->alloc && a->free ? a->alloc(size, a->user) : malloc(size);
}

static inline void hol_alloc_release(const hol_alloc *a, void *ptr)
{
    if (a && a->alloc && a->free)
        a->free(ptr, a->user);
    else
        free(ptr);
}

#endif

/* parasol's MULT_FRONT plug-in: a thin C layer over CHOLMOD's supernodal Cholesky
 * (SuiteSparse, Debian libsuitesparse-dev), loaded at run time by src/solvers/
 * cholmod_solver.f90 (dlopen) so that runs without METHODE='MULT_FRONT' never load CHOLMOD.
 *
 * The Fortran side owns the matrix: the upper triangle compressed by columns with 1-based
 * indices (src/assembly/sparse_matrix.f90). This layer keeps one CHOLMOD copy of it
 * (0-based, stype = +1: upper triangle stored), its symbolic analysis and its factor.
 * Every entry point returns 0 on success, or a negative code:
 *   -1 out of memory, -2 CHOLMOD error (status in *info), -3 bad argument.
 * C is used here, and only here, because cholmod_common is a large C structure whose
 * layout Fortran cannot declare portably; the entry points take plain arrays and are
 * declared bind(C) on the Fortran side (iso_c_binding).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <sys/mman.h>
#include <suitesparse/cholmod.h>

/* Large blocks (the factor, CHOLMOD's copies of the matrix) are aligned on 2 MB and advised
 * for transparent huge pages (madvise MADV_HUGEPAGE; Linux, where THP is "madvise", the
 * Debian default): a 128x512 plate's factor is 757 MB, i.e. 185 000 first-touch page
 * faults of 4 kB, which on the project's VM cost several seconds of system time and TLB
 * misses; with 2 MB pages the first factorization took 6.5 s instead of 9.4 s
 * (doc/performance.md, "Contact Newton"). Elsewhere (no THP) madvise fails harmlessly. */
#define PARASOL_HUGE_BLOCK ((size_t) 4 << 20)
#define PARASOL_HUGE_ALIGN ((size_t) 2 << 20)

static void *huge_malloc(size_t size)
{
    void *p = NULL;
    if (size < PARASOL_HUGE_BLOCK) return malloc(size);
    if (posix_memalign(&p, PARASOL_HUGE_ALIGN, size) != 0) return NULL;
#ifdef MADV_HUGEPAGE
    (void) madvise(p, size - size % PARASOL_HUGE_ALIGN, MADV_HUGEPAGE);
#endif
    return p;
}

static void *huge_calloc(size_t n, size_t size)
{
    void *p;
    if (size != 0 && n > ((size_t) -1) / size) return NULL;
    if (n * size < PARASOL_HUGE_BLOCK) return calloc(n, size);
    p = huge_malloc(n * size);
    if (p != NULL) memset(p, 0, n * size);
    return p;
}

static void *huge_realloc(void *old, size_t size)
{
    /* realloc keeps the contents; a grown block may lose the alignment and the advice,
     * which only costs the page-size benefit (CHOLMOD reallocates rarely) */
    return realloc(old, size);
}

typedef struct {
    cholmod_common common;
    cholmod_sparse *a;      /* the matrix (pattern fixed at analyse, values per factor) */
    cholmod_factor *l;      /* symbolic, then numeric factor */
    int64_t n;
} parasol_cholmod_t;

/* ordering: 0 METIS (nested dissection), 1 AMD, 2 natural. */
void *parasol_cholmod_create(int32_t ordering)
{
    parasol_cholmod_t *h = calloc(1, sizeof(parasol_cholmod_t));
    if (h == NULL) return NULL;
    /* SuiteSparse's allocator is a process-wide setting: set before CHOLMOD allocates
     * anything, always to the same functions (free is the C library's: posix_memalign'ed
     * blocks are freed by free) */
    SuiteSparse_config.malloc_func = huge_malloc;
    SuiteSparse_config.calloc_func = huge_calloc;
    SuiteSparse_config.realloc_func = huge_realloc;
    SuiteSparse_config.free_func = free;
    cholmod_l_start(&h->common);
    h->common.print = 0;               /* errors come back as status codes */
    h->common.error_handler = NULL;
    h->common.nmethods = 1;
    h->common.method[0].ordering = ordering == 0 ? CHOLMOD_METIS
                                 : ordering == 1 ? CHOLMOD_AMD : CHOLMOD_NATURAL;
    h->common.postorder = 1;
    h->common.supernodal = CHOLMOD_SUPERNODAL;
    h->common.final_ll = 1;            /* supernodal factors are LL' anyway */
    h->common.quick_return_if_not_posdef = 1;
    return h;
}

void parasol_cholmod_destroy(void *handle)
{
    parasol_cholmod_t *h = handle;
    if (h == NULL) return;
    if (h->l != NULL) cholmod_l_free_factor(&h->l, &h->common);
    if (h->a != NULL) cholmod_l_free_sparse(&h->a, &h->common);
    cholmod_l_finish(&h->common);
    free(h);
}

/* Symbolic analysis of the pattern: col_ptr (n+1, 1-based, int64), row_index (nnz, 1-based,
 * int32). On return: factor_entries = nonzeros of L, flops = its flop count. */
int32_t parasol_cholmod_analyse(void *handle, int64_t n, const int64_t *col_ptr,
                                const int32_t *row_index, int64_t *factor_entries,
                                double *flops, int32_t *info)
{
    parasol_cholmod_t *h = handle;
    int64_t nnz, j, k;
    SuiteSparse_long *p, *i;
    *info = 0;
    if (h == NULL || n < 0) return -3;
    if (h->l != NULL) cholmod_l_free_factor(&h->l, &h->common);
    if (h->a != NULL) cholmod_l_free_sparse(&h->a, &h->common);
    nnz = col_ptr[n] - 1;
    h->a = cholmod_l_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, &h->common);
    if (h->a == NULL) { *info = h->common.status; return -1; }
    p = h->a->p;
    i = h->a->i;
    for (j = 0; j <= n; j++) p[j] = col_ptr[j] - 1;
    for (k = 0; k < nnz; k++) i[k] = row_index[k] - 1;
    memset(h->a->x, 0, (size_t) (nnz > 0 ? nnz : 1) * sizeof(double));
    h->n = n;
    h->l = cholmod_l_analyze(h->a, &h->common);
    if (h->l == NULL || h->common.status < 0) { *info = h->common.status; return -2; }
    *factor_entries = (int64_t) h->common.lnz;
    *flops = h->common.fl;
    return 0;
}

/* Numerical factorization of `values` (nnz, the analysed pattern) with the equations
 * hold[0..n_hold-1] (1-based) held: their diagonal gets penalty x max(|a_jj|, scale).
 * minor = 0 when the factorization went through, else the 1-based equation whose pivot was
 * not positive (the factor is then incomplete). pivots (n): the pivot of each equation,
 * L_jj^2, in the caller's numbering (only when minor = 0). */
int32_t parasol_cholmod_factor(void *handle, const double *values, int64_t n_hold,
                               const int64_t *hold, double penalty, double scale,
                               int64_t *minor, double *pivots, int32_t *info)
{
    parasol_cholmod_t *h = handle;
    int64_t nnz, k, j, s, c, nscol, nsrow;
    double *x, *lx, d;
    SuiteSparse_long *p, *perm, *super, *lpx;
    *info = 0;
    *minor = 0;
    if (h == NULL || h->a == NULL || h->l == NULL) return -3;
    p = h->a->p;
    nnz = p[h->n];
    x = h->a->x;
    memcpy(x, values, (size_t) nnz * sizeof(double));
    for (k = 0; k < n_hold; k++) {
        j = hold[k] - 1;
        if (j < 0 || j >= h->n || p[j + 1] <= p[j]) return -3;
        d = fabs(x[p[j + 1] - 1]);         /* the diagonal is the column's last entry */
        x[p[j + 1] - 1] += penalty * (d > 0.0 ? d : scale);
    }
    if (!cholmod_l_factorize(h->a, h->l, &h->common)) {
        *info = h->common.status;
        return -2;
    }
    perm = h->l->Perm;
    if (h->common.status == CHOLMOD_NOT_POSDEF) {
        *minor = (int64_t) perm[h->l->minor] + 1;
        return 0;
    }
    if (h->common.status < 0) { *info = h->common.status; return -2; }
    if (!h->l->is_super) return -3;
    super = h->l->super;
    lpx = h->l->px;
    lx = h->l->x;
    for (s = 0; s < (int64_t) h->l->nsuper; s++) {
        nscol = super[s + 1] - super[s];
        nsrow = ((SuiteSparse_long *) h->l->pi)[s + 1] - ((SuiteSparse_long *) h->l->pi)[s];
        for (c = 0; c < nscol; c++) {
            d = lx[lpx[s] + c * nsrow + c];
            pivots[perm[super[s] + c]] = d * d;
        }
    }
    return 0;
}

/* b (n x nrhs, column-major) <- A^-1 b with the factor. */
int32_t parasol_cholmod_solve(void *handle, int64_t nrhs, double *b, int32_t *info)
{
    parasol_cholmod_t *h = handle;
    cholmod_dense rhs, *x;
    *info = 0;
    if (h == NULL || h->l == NULL || nrhs < 0) return -3;
    if (h->n == 0 || nrhs == 0) return 0;
    memset(&rhs, 0, sizeof(rhs));
    rhs.nrow = h->n;
    rhs.ncol = nrhs;
    rhs.nzmax = h->n * nrhs;
    rhs.d = h->n;
    rhs.x = b;
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    x = cholmod_l_solve(CHOLMOD_A, h->l, &rhs, &h->common);
    if (x == NULL) { *info = h->common.status; return -2; }
    memcpy(b, x->x, (size_t) (h->n * nrhs) * sizeof(double));
    cholmod_l_free_dense(&x, &h->common);
    return 0;
}

/* Ordering CHOLMOD used (CHOLMOD_NATURAL/AMD/METIS ...) and the bytes of memory it holds. */
int32_t parasol_cholmod_info(void *handle, int32_t *ordering, int64_t *bytes_in_use,
                             int64_t *peak_bytes)
{
    parasol_cholmod_t *h = handle;
    if (h == NULL) return -3;
    *ordering = h->l != NULL ? h->l->ordering : -1;
    *bytes_in_use = (int64_t) h->common.memory_inuse;
    *peak_bytes = (int64_t) h->common.memory_usage;
    return 0;
}

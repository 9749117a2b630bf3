/* SPDX-License-Identifier: MIT */
/* The engine's slow sample, written once, instantiated by src/tcm_engine.h
 * for the kinds its emit() ends (polynomials, tables, the kinds evaluated
 * out of line) and by each kind that derives its branches itself
 * (src/kind_everett*.h), with that kind's end of a sample inline: its own
 * copy of repeats, reversals, wipe-outs and the edges, so that no kind pays
 * for another's code or a call on its worst path (S->slow: the instance's
 * copy). No include guard: included once per instantiation, after the
 * engine. Parameters, undefined at the end:
 *   TCM_SLOW(n)                the copy's names
 *   TCM_SLOW_EMIT(S, x, how, derive)  the end of a slow sample (emit()'s
 *                              contract: TCM_ROSE/TCM_FELL, TCM_KEEP or
 *                              TCM_DERIVE_RISE/FALL)
 *   TCM_SLOW_PER_BRANCH        1 if the kind derives every branch
 *                              (TCM_PER_BRANCH: settle() derives, an edge
 *                              sample starts the major rising branch) */
#if !defined(TCM_SLOW) || !defined(TCM_SLOW_EMIT) || !defined(TCM_SLOW_PER_BRANCH)
#error "tcm_slow.h: define TCM_SLOW, TCM_SLOW_EMIT and TCM_SLOW_PER_BRANCH"
#endif

/* The detour flags the plain path ignores: the kind's own. */
#if TCM_SLOW_PER_BRANCH
#define TCM_SLOW_DETOUR_OK TCM_PER_BRANCH
#else
#define TCM_SLOW_DETOUR_OK 0u
#endif

static TCM_Y TCM_SLOW(step_slow)(hyst_tcm_t *S, TCM_ARG x_in);

/* settle() of this copy's kinds: the engine's own for a kind that derives
 * its branches, one without that test for the others. */
#if TCM_SLOW_PER_BRANCH
#define TCM_SLOW_SETTLE(S, x) TCM_NAME(settle)((S), (x))
#else
static void TCM_SLOW(settle_slow)(hyst_tcm_t *S, TCM_X x) { TCM_NAME(settle_as)(S, x, 0); }
#define TCM_SLOW_SETTLE(S, x) TCM_SLOW(settle_slow)((S), (x))
#endif


#if TCM_SLOW_PER_BRANCH
/* finish() of a sample that reached lo or hi (not TCM_SLOW_ONLY): back on
 * the major rising branch from A0, derived and evaluated at once. Out of
 * line: step_edge() keeps no stack frame. */
static TCM_NOINLINE TCM_Y TCM_SLOW(edge_derived)(hyst_tcm_t *S, TCM_X x, TCM_X x_prev)
{
    TCM_Y y;
    TCM_NAME(settle_rising)(S, x, 0u, 0u);
    y = TCM_SLOW_EMIT(S, x, x > x_prev ? TCM_ROSE : TCM_FELL, TCM_DERIVE_RISE);
    TCM_NAME(ended_not_ok)(S);
    return y;
}
#endif

/* Ends a slow sample whose input rose or fell (how: TCM_ROSE, TCM_FELL):
 * caches the branch now current and evaluates it. A status other than OK
 * closes the fast path for the next sample. */
static TCM_Y TCM_SLOW(finish)(hyst_tcm_t *S, TCM_X x, int how)
{
    TCM_Y y;
    TCM_SLOW_SETTLE(S, x);
    if ((S->detour & TCM_SLOW_ONLY) == 0u) {
        y = TCM_SLOW_EMIT(S, x, how, TCM_KEEP); /* serves a pending request */
    } else {
        y = TCM_NAME(slow_only)(S, x, how);
        YV(S->y_prev) = y;
        if (S->horner == HYST_HORNER_REQUEST_) { /* emit() serves the other curves' requests */
            TCM_NAME(serve)(S);
        }
    }
    TCM_NAME(ended_not_ok)(S);
    return y;
}

/* finish() on the detour paths, which every sample with TCM_BOOK takes.
 * TCM_SETTLING implies TCM_BOOK, so the plain path and step_edge() without
 * bookkeeping call finish() itself: the check stays off the clamped worst
 * path. */
static TCM_Y TCM_SLOW(finish_book)(hyst_tcm_t *S, TCM_X x, int how)
{
    const TCM_Y y = TCM_SLOW(finish)(S, x, how);
    if ((S->detour & TCM_SETTLING) != 0u) {
        TCM_NAME(settle_bound)(S, y);
    }
    return y;
}

/* Out of line, off the worst path: NaN, inputs outside (lo, hi) (clamped)
 * and inputs at lo or hi, which pass every stored TP: back at A0 without a
 * search. */
static TCM_NOINLINE TCM_Y TCM_SLOW(step_edge)(hyst_tcm_t *S, TCM_ARG x_in)
{
    const TCM_X x_prev = XV(S->window[S->moving_end]);
    TCM_X x;
    /* not fresh(): a TCM_STALE left set costs the next sample a detour that
     * clears it, where clearing it here would cost the worst path */
    S->status = HYST_OK;
    if (!TCM_ADMIT(S, x_in, &x) || x == x_prev) { /* NaN, or clamped where it was */
        TCM_NAME(ended_not_ok)(S);
        if (S->horner == HYST_HORNER_REQUEST_) { /* its requests, as every step's */
            return TCM_NAME(serve_unmoved)(S);
        }
        return YV(S->y_prev);
    }
    S->n_ltp = 1u;
    S->n_rtp = 0u;
    if ((S->detour & TCM_BOOK) != 0u) { /* a merge or an excursion was alive */
        TCM_NAME(wiped)(S, 0u);
        return TCM_SLOW(finish_book)(S, x, x > x_prev ? TCM_ROSE : TCM_FELL);
    }
#if TCM_SLOW_PER_BRANCH
    if ((S->detour & TCM_SLOW_ONLY) == 0u) { /* on the major rising branch from A0 */
        return TCM_SLOW(edge_derived)(S, x, x_prev);
    }
#endif
    return TCM_SLOW(finish)(S, x, x > x_prev ? TCM_ROSE : TCM_FELL);
}

/* Reversal on a falling branch without a wipe-out, with a detour (a flag
 * of S->detour, or a full LTP array): (x_prev, y_prev) becomes LTP nl,
 * unless the deadband skips it or a full array merges it. */
static TCM_NOINLINE TCM_Y TCM_SLOW(reverse_up)(hyst_tcm_t *S, TCM_X x, TCM_X x_prev)
{
    size_t nl = S->n_ltp, nr = S->n_rtp;
    TCM_NAME(fresh)(S);
    TCM_NAME(release_held)(S);
    if (TCM_NAME(skips)(S, (TCM_X)(XV(S->xrtp)[nr - 1u] - x_prev))) {
        TCM_SKIP(S, x_prev, XV(S->xrtp)[nr - 1u]); /* keep falling */
    } else {
        if (nl == S->capacity) {
            /* Only the LTP array can fill (A0 takes one of its entries). */
            S->status = HYST_WARN_FULL;
            S->events |= HYST_EVENT_FULL;
            TCM_NAME(merge)(S, x_prev, &nr);
        } else {
            XV(S->xltp)[nl] = TCM_NORM(x_prev);
            YV(S->yltp)[nl] = YV(S->y_prev);
            ++nl;
        }
        S->n_ltp = nl;
        S->n_rtp = nr;
        TCM_NAME(window_closed)(S);
    }
    return TCM_SLOW(finish_book)(S, x, TCM_ROSE);
}

/* Reversal on a rising branch without a wipe-out, with a detour:
 * (x_prev, y_prev) becomes RTP nr (nr < nl <= capacity: always room),
 * unless the deadband skips it. */
static TCM_NOINLINE TCM_Y TCM_SLOW(reverse_down)(hyst_tcm_t *S, TCM_X x, TCM_X x_prev)
{
    const size_t nl = S->n_ltp, nr = S->n_rtp;
    TCM_NAME(fresh)(S);
    TCM_NAME(release_held)(S);
    if (TCM_NAME(skips)(S, (TCM_X)(x_prev - XV(S->xltp)[nl - 1u]))) {
        TCM_SKIP(S, XV(S->xltp)[nl - 1u], x_prev); /* keep rising */
    } else {
        XV(S->xrtp)[nr] = TCM_NORM(x_prev);
        YV(S->yrtp)[nr] = YV(S->y_prev);
        S->n_rtp = nr + 1u;
        TCM_NAME(window_closed)(S);
    }
    return TCM_SLOW(finish_book)(S, x, TCM_FELL);
}

/* A wipe-out down to stack depth `depth` with a detour: bookkeeping, then
 * the output. */
static TCM_NOINLINE TCM_Y TCM_SLOW(wiped_detour)(hyst_tcm_t *S, TCM_X x, size_t depth, int how)
{
    TCM_NAME(fresh)(S);
    TCM_NAME(wiped)(S, depth);
    return TCM_SLOW(finish_book)(S, x, how);
}

/* A slow sample that stays on its branch (the window was closed). */
static TCM_NOINLINE TCM_Y TCM_SLOW(carry_on)(hyst_tcm_t *S, TCM_X x, int how)
{
    TCM_NAME(fresh)(S);
    return TCM_SLOW(finish_book)(S, x, how);
}

/* Everything but the fast path, for an input strictly inside (lo, hi):
 * repeats, reversals, wipe-out. A wipe-out is always "rising to RTP nr-1 or
 * beyond" or "falling to LTP nl-1 or below", after a reversal or not, so each
 * search has one call site. The plain path (no detour: a polynomial curve,
 * nothing merged, no deadband) ends in one settle and one Horner evaluation
 * per direction; merges, the deadband and other curve kinds leave it through
 * one test of S->detour. The asymmetric kinds take it too, their branch's
 * coefficients derived after the settle (TCM_PER_BRANCH). */
static TCM_Y TCM_SLOW(step_slow)(hyst_tcm_t *S, TCM_ARG x_in)
{
    TCM_X x, x_prev;
    size_t nl, nr;

    ++S->seq; /* every change but a fast-path sample's (snapshot.c) */
    x_prev = XV(S->window[S->moving_end]);
    nl = S->n_ltp;
    nr = S->n_rtp;
    /* Domain checks folded into the direction test: rising can only leave
     * through hi, falling through lo; NaN is neither rising nor falling. */
    if (x_in > x_prev) {
        if (!(x_in < XV(S->hi))) {
            return TCM_SLOW(step_edge)(S, x_in);
        }
        x = (TCM_X)x_in;
        if (nr > 0u && x >= XV(S->xrtp)[nr - 1u]) {
            /* wipe-out: RTPs at or below x go, with the LTPs above them */
            nr = TCM_RTP_ABOVE(XV(S->xrtp), nr - 1u, x);
            S->n_ltp = nr + 1u;
            S->n_rtp = nr;
            if ((S->detour & (TCM_SLOW_ONLY | TCM_BOOK | TCM_STALE)) != 0u) {
                return TCM_SLOW(wiped_detour)(S, x, 2u * nr + 1u, TCM_ROSE);
            }
            nl = nr; /* the current LTP's index */
        } else if (nl == nr && (S->detour & ~TCM_SLOW_DETOUR_OK) == 0u && nl < S->capacity) {
            /* reversal on a falling branch: (x_prev, y_prev) becomes LTP nl */
            XV(S->xltp)[nl] = TCM_NORM(x_prev);
            YV(S->yltp)[nl] = YV(S->y_prev);
            S->n_ltp = nl + 1u;
        } else {
            return nl == nr ? TCM_SLOW(reverse_up)(S, x, x_prev) : TCM_SLOW(carry_on)(S, x, TCM_ROSE);
        }
        TCM_NAME(settle_rising)(S, x, nl, nr);
        /* one emit per direction: its guard's direction is then a constant
         * (and the asymmetric kinds derive the new branch's shape in it) */
        return TCM_SLOW_EMIT(S, x, TCM_ROSE, TCM_DERIVE_RISE);
    } else if (x_in < x_prev) {
        if (!(x_in > XV(S->lo))) {
            return TCM_SLOW(step_edge)(S, x_in);
        }
        x = (TCM_X)x_in;
        if (x <= XV(S->xltp)[nl - 1u]) {
            /* wipe-out: LTPs at or above x go, with the RTPs above them;
             * A0 = lo < x always survives */
            nl = TCM_LTP_BELOW(XV(S->xltp), nl - 1u, x);
            S->n_ltp = nl;
            S->n_rtp = nl;
            if ((S->detour & (TCM_SLOW_ONLY | TCM_BOOK | TCM_STALE)) != 0u) {
                return TCM_SLOW(wiped_detour)(S, x, 2u * nl, TCM_FELL);
            }
            nr = nl - 1u; /* the current RTP's index (nl >= 1: A0) */
        } else if (nl > nr && (S->detour & ~TCM_SLOW_DETOUR_OK) == 0u) {
            /* reversal on a rising branch: (x_prev, y_prev) becomes RTP nr
             * (nr < nl <= capacity: always room) */
            XV(S->xrtp)[nr] = TCM_NORM(x_prev);
            YV(S->yrtp)[nr] = YV(S->y_prev);
            S->n_rtp = nr + 1u;
        } else {
            return nl > nr ? TCM_SLOW(reverse_down)(S, x, x_prev) : TCM_SLOW(carry_on)(S, x, TCM_FELL);
        }
        TCM_NAME(settle_falling)(S, x, nr);
        return TCM_SLOW_EMIT(S, x, TCM_FELL, TCM_DERIVE_FALL);
    }
    /* Always true for integer codes; false for a NaN real input: */
    /* cppcheck-suppress knownConditionTrueFalse */
    else if (x_in == x_prev) { /* repeated samples create no TP */
        TCM_NAME(fresh)(S);
        if (S->horner == HYST_HORNER_REQUEST_) {
            return TCM_NAME(emit_rare)(S, x_prev, TCM_REPEAT);
        }
        return YV(S->y_prev); /* a closed window stays closed: the next move reopens it */
    }
    return TCM_SLOW(step_edge)(S, x_in); /* NaN */
}

#undef TCM_SLOW_DETOUR_OK
#undef TCM_SLOW_SETTLE
#undef TCM_SLOW
#undef TCM_SLOW_EMIT
#undef TCM_SLOW_PER_BRANCH

% SPDX-License-Identifier: MIT
function [y, status, tp_count] = hyst_sim(model, x, varargin)
% HYST_SIM  Runs the hysteresis model (TCM) over the samples X.
%   Y = HYST_SIM(MODEL, X) is the model's output for the input sequence X,
%   from the start state (lo, f0(lo)), by one block call of the C library:
%   X of class double runs hyst_f64_process, single runs hyst_f32_process
%   (a Cortex-M4F fuses its multiply-adds: its single results can differ in
%   the last bits, docs/porting.md). Y has the class and the shape of X.
%   MODEL is a struct with fields coeffs (f0, highest power first), lo, hi:
%   what HYST_FIT and HYST_MODEL_LOAD return; or, for the asymmetric kind
%   (hyst_everett_t: hyst_*_curve_from_everett, hyst_*_init_curve), with
%   fields kind 'everett', degree (1..4), lo, hi, y_lo (the output at lo)
%   and terms, the coefficients e[i-1][j] of w^i t^j of the branch function
%   E for i = 1..degree, then j = 0..degree-i (docs/matlab.md); or, for the
%   asymmetric kind on a grid (hyst_everett_grid_t:
%   hyst_*_curve_from_everett_grid), with fields kind 'everett_grid', y_lo,
%   knots (lo first, hi last) and weights (the cells' masses), as
%   HYST_MODEL_LOAD returns a model file of that kind; or, for the
%   symmetric kind whose f0 is a monotone cubic spline on uniform knots
%   (hyst_spline_t: hyst_*_curve_from_spline), with fields kind 'spline',
%   lo, hi, values and slopes (f0 and its slope at the K + 1 knots
%   lo + k (hi - lo) / K, K 1..32).
%
%   A MODEL with a creep term (the fields creep_tau, 1 to 4 time constants
%   in samples, and creep_weight, as many weights: what HYST_MODEL_LOAD and
%   HYST_FIT return for one) adds to each output sum_k creep_weight(k) s_k,
%   s_k a first-order lag (hyst/creep.h) of the input as the model took it
%   (clamped to [lo, hi]) from lo at rest, strictly causal: the numbers of
%   'hyst sim --model' (docs/matlab.md, "Creep"). A MODEL with a rate term
%   (fields rate_tau and rate_weight, scalars: docs/rate.md) adds
%   rate_weight times a low-pass, of time constant rate_tau samples, of the
%   change of the input as the model took it, 0 at rest: again the numbers
%   of 'hyst sim --model'.
%
%   Options (name/value): 'capacity' turning points per array (default
%   2048: never full for inputs taking at most 4096 distinct values),
%   'deadband' noise deadband (default 0).
%
%   [Y, STATUS, TP_COUNT] = HYST_SIM(...) also returns the status of the block
%   call (0; 1 an input was clamped to [lo, hi]; 2 memory full; -7 a NaN/Inf
%   sample was ignored) and the turning points stored at the end.
%   An invalid model raises an error hyst:<status name>, e.g.
%   hyst:ERR_NOT_INCREASING (docs/matlab.md).
  [y, status, tp_count] = hyst_run('sim', model, x, varargin);
end

% SPDX-License-Identifier: MIT
function [x, status, tp_count, inv_err] = hyst_inv(model, y, varargin)
% HYST_INV  The compensator: the drive X that gives each desired output Y.
%   X = HYST_INV(MODEL, Y) runs the inverse model (include/hyst/inverse.h:
%   hyst_f64_init_inverse_exact, or hyst_f32_init_inverse_exact for Y of class single)
%   over Y, from (f0(lo), lo). HYST_SIM(MODEL, X) gives Y back (within the
%   rounding of the inverse); a desired output outside [f0(lo), f0(hi)] is
%   clamped (STATUS 1). For the asymmetric kind (a struct of kind 'everett',
%   as HYST_SIM takes it) the compensator is hyst_curve_inverse() of its
%   curve: desired outputs on [y_lo, y_lo + E(hi, lo)], each branch solved
%   (Newton's iteration, bracketed), the drive within about 1e-12 (double)
%   or 1e-6 (single) of hi - lo. For kind 'everett_grid' it is
%   hyst_*_curve_everett_grid_inverse(), each branch solved in closed form,
%   and for kind 'spline' hyst_curve_spline_inverse(), each drive solved on
%   f0's cubic piece (exact at the knots; a flat piece has no inverse:
%   hyst:ERR_NOT_INVERTIBLE). Kind everett_grid has no table ('intervals'
%   and 'rows' are refused). Options and outputs as HYST_SIM.
%
%   HYST_INV(MODEL, Y, 'intervals', N) runs the tabulated compensator
%   firmware runs, bit for bit (the same C code; Y double: f64, single: f32):
%    - a polynomial f0: hyst_*_init_inverse_table with an N-interval table
%      (HYST_INIT_INVERSE uses HYST_INV_TABLE = 256);
%    - kind 'spline': hyst_*_curve_spline_inverse_table with an N-interval
%      table (intervals that miss its tolerance solved per sample instead);
%    - the asymmetric kind: hyst_*_curve_everett_inverse_table with R rows of
%      N intervals per direction, HYST_INV(MODEL, Y, 'intervals', N, 'rows', R),
%      R 3..4096, by default the library's HYST_EVERETT_INV_ROWS (16; firmware's
%      default N is HYST_EVERETT_INV_INTERVALS, 32: hyst_mex('config') gives
%      both); with the default table the drive error stays below 1e-5 of
%      hi - lo (docs/pi_and_inverse.md).
%   N is 1..2^20; 0, the default, is the exact (or solved) compensator, and
%   'rows' needs N > 0 and the asymmetric kind. INV_ERR is the worst error
%   against the exact inverse that the table's init measured, as a fraction
%   of the drive range (hyst_curve_inverse_error(); 0 without a table).
%
%   A MODEL with a creep term (fields creep_tau, creep_weight, as HYST_SIM
%   takes them) gives, for each desired output Y(k), the compensator's drive
%   for Y(k) less the creep's contribution (known before the sample: it
%   depends on the drives before), and the creep's lags then take that
%   drive in: the numbers of 'hyst inv --model' (which, like HYST_INV, does
%   not compensate the model's delay). With a table, the table is the
%   hysteresis model's alone, as firmware's. A rate term (fields rate_tau,
%   rate_weight) is subtracted the same way, with the creep's.
  [x, status, tp_count, inv_err] = hyst_run('inv', model, y, varargin);
end

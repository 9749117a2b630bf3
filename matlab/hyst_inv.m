% SPDX-License-Identifier: MIT
function [x, status, tp_count, inv_err] = hyst_inv(model, y, varargin)
% HYST_INV  The compensator: the drive X that gives each desired output Y.
%   X = HYST_INV(MODEL, Y) runs the inverse model (include/hyst/inverse.h:
%   hyst_f64_init_inverse_exact, or hyst_f32_init_inverse_exact for Y of class single)
%   over Y, from (f0(lo), lo). HYST_SIM(MODEL, X) gives Y back (within the
%   rounding of the inverse); a desired output outside [f0(lo), f0(hi)] is
%   clamped (STATUS 1). For the asymmetric kind (a struct of kind 'everett',
%   as HYST_SIM takes it) the compensator is hyst_curve_inverse() of its
%   curve: desired outputs on [y_lo, y_lo + E(hi, lo)], the drive within
%   about 1e-12 (double) or 1e-6 (single) of hi - lo. Options and outputs as
%   HYST_SIM.
%
%   HYST_INV(MODEL, Y, 'intervals', N) runs, for a polynomial f0, the
%   compensator firmware runs (HYST_INIT_INVERSE: hyst_*_init_inverse_table
%   with an N-interval table; HYST_INV_TABLE = 256 by default there), bit for
%   bit; INV_ERR is the worst error against the exact inverse that its init
%   measured, as a fraction of the drive range (0 for the exact one, the
%   default 'intervals' 0).
  [x, status, tp_count, inv_err] = hyst_run('inv', model, y, varargin);
end

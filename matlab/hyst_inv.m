% SPDX-License-Identifier: MIT
function [x, status, tp_count] = hyst_inv(model, y, varargin)
% HYST_INV  The compensator: the drive X that gives each desired output Y.
%   X = HYST_INV(MODEL, Y) runs the inverse model (include/hyst/inverse.h:
%   hyst_f64_init_inverse, or hyst_f32_init_inverse for Y of class single)
%   over Y, from (f0(lo), lo). HYST_SIM(MODEL, X) gives Y back (within the
%   rounding of the inverse); a desired output outside [f0(lo), f0(hi)] is
%   clamped (STATUS 1). Options and outputs as HYST_SIM. The library has no
%   inverse of the asymmetric kind: such a model raises hyst:usage.
  opts = hyst_options(varargin, struct('capacity', 2048, 'deadband', 0), 'hyst_inv');
  p = hyst_model_parts(model, 'hyst_inv');
  if ~strcmp(p.kind, 'poly')
    error('hyst:usage', 'hyst_inv: no compensator of the kind ''%s'' (poly only)', p.kind);
  end
  [x, status, tp_count] = hyst_mex('inv', p.coeffs, p.lo, p.hi, y, double(opts.capacity), ...
                                   double(opts.deadband));
end

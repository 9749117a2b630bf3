% SPDX-License-Identifier: MIT
function [suffix, args] = hyst_model_args(p)
% HYST_MODEL_ARGS  The model P (HYST_MODEL_PARTS) as the gateway's commands
%   of its kind take it: hyst_mex(['sim' SUFFIX], ARGS{:}, x, ...), and
%   'inv', 'holdout' alike. SUFFIX '' with ARGS coeffs, lo, hi (f0); '_everett'
%   with degree, lo, hi, y_lo, terms; '_grid' with knots, weights, y_lo;
%   '_spline' with lo, hi, values, slopes.
  switch p.kind
    case 'everett'
      suffix = '_everett';
      args = {p.degree, p.lo, p.hi, p.y_lo, p.terms};
    case 'everett_grid'
      suffix = '_grid';
      args = {p.knots, p.weights, p.y_lo};
    case 'spline'
      suffix = '_spline';
      args = {p.lo, p.hi, p.values, p.slopes};
    otherwise
      suffix = '';
      args = {p.coeffs, p.lo, p.hi};
  end
end

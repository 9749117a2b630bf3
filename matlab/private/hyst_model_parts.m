% SPDX-License-Identifier: MIT
function [coeffs, lo, hi] = hyst_model_parts(model, caller)
% HYST_MODEL_PARTS  The coefficients (a row, highest power first) and the
% domain of a model struct (fields coeffs, lo, hi: what hyst_fit and
% hyst_model_load return).
  if ~isstruct(model) || ~all(isfield(model, {'coeffs', 'lo', 'hi'}))
    error('hyst:usage', '%s: the model is a struct with fields coeffs, lo, hi', caller);
  end
  coeffs = double(model.coeffs(:)');
  lo = double(model.lo);
  hi = double(model.hi);
end

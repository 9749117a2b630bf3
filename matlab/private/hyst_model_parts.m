% SPDX-License-Identifier: MIT
function p = hyst_model_parts(model, caller)
% HYST_MODEL_PARTS  The parts of a model struct (what hyst_fit and
% hyst_model_load return), as doubles: P.kind 'poly' with P.coeffs (a row,
% highest power first), P.lo, P.hi; or P.kind 'everett' (MODEL.kind is
% 'everett') with P.degree, P.lo, P.hi, P.y_lo, P.terms (a row); or P.kind
% 'everett_grid' with P.y_lo, P.knots, P.weights (rows), P.lo and P.hi the
% first and the last knot; or P.kind 'spline' (f0 a monotone cubic spline
% on uniform knots) with P.lo, P.hi, P.values and P.slopes (rows: f0 and
% its slope at the K + 1 knots lo + k (hi - lo) / K). P.delay:
% MODEL.delay, 0 without one (the sensor's delay in samples: not part of the
% model, kept in its file and stated in its header). P.creep_tau and
% P.creep_weight: the creep term's time constants (samples) and weights,
% rows, from MODEL's fields of those names ([] and [] without: no creep
% term). P.rate_tau and P.rate_weight: the rate term's time constant
% (samples) and weight, from MODEL's fields of those names ([] and []
% without: no rate term). Not checked here: HYST_MODEL_CHECK, or the library.
  if isstruct(model) && isfield(model, 'kind') && strcmp(model.kind, 'everett_grid')
    if ~all(isfield(model, {'y_lo', 'knots', 'weights'}))
      error('hyst:usage', '%s: an everett_grid model is a struct with fields kind, y_lo, knots, weights', ...
            caller);
    end
    p = struct('kind', 'everett_grid', 'y_lo', double(model.y_lo), ...
               'knots', double(model.knots(:)'), 'weights', double(model.weights(:)'));
    p.lo = p.knots(1);
    p.hi = p.knots(end);
  elseif isstruct(model) && isfield(model, 'kind') && strcmp(model.kind, 'spline')
    if ~all(isfield(model, {'lo', 'hi', 'values', 'slopes'}))
      error('hyst:usage', '%s: a spline model is a struct with fields kind, lo, hi, values, slopes', ...
            caller);
    end
    p = struct('kind', 'spline', 'lo', double(model.lo), 'hi', double(model.hi), ...
               'values', double(model.values(:)'), 'slopes', double(model.slopes(:)'));
  elseif isstruct(model) && isfield(model, 'kind') && strcmp(model.kind, 'everett')
    if ~all(isfield(model, {'degree', 'lo', 'hi', 'y_lo', 'terms'}))
      error('hyst:usage', '%s: an everett model is a struct with fields kind, degree, lo, hi, y_lo, terms', ...
            caller);
    end
    p = struct('kind', 'everett', 'degree', double(model.degree), 'lo', double(model.lo), ...
               'hi', double(model.hi), 'y_lo', double(model.y_lo), 'terms', double(model.terms(:)'));
  else
    if ~isstruct(model) || ~all(isfield(model, {'coeffs', 'lo', 'hi'})) || ...
       (isfield(model, 'kind') && ~strcmp(model.kind, 'poly'))
      error('hyst:usage', ['%s: the model is a struct with fields coeffs, lo, hi (or kind ' ...
                           '''everett'', degree, lo, hi, y_lo, terms; kind ''everett_grid'', ' ...
                           'y_lo, knots, weights; kind ''spline'', lo, hi, values, slopes)'], caller);
    end
    p = struct('kind', 'poly', 'coeffs', double(model.coeffs(:)'), 'lo', double(model.lo), ...
               'hi', double(model.hi));
  end
  p.delay = 0;
  if isfield(model, 'delay')
    p.delay = double(model.delay);
  end
  % the range the model was identified on, [LO HI] (a model file's key
  % identified), or [] when not recorded
  p.identified = [];
  if isfield(model, 'identified')
    p.identified = double(model.identified(:)');
  end
  p.creep_tau = [];
  p.creep_weight = [];
  if isfield(model, 'creep_tau') ~= isfield(model, 'creep_weight')
    error('hyst:usage', '%s: a creep term needs the fields creep_tau and creep_weight (both or neither)', ...
          caller);
  end
  if isfield(model, 'creep_tau')
    if ~isnumeric(model.creep_tau) || ~isnumeric(model.creep_weight) || ...
       ~isreal(model.creep_tau) || ~isreal(model.creep_weight)
      error('hyst:usage', '%s: creep_tau and creep_weight are real vectors', caller);
    end
    p.creep_tau = double(model.creep_tau(:)');
    p.creep_weight = double(model.creep_weight(:)');
  end
  p.rate_tau = [];
  p.rate_weight = [];
  if isfield(model, 'rate_tau') ~= isfield(model, 'rate_weight')
    error('hyst:usage', '%s: a rate term needs the fields rate_tau and rate_weight (both or neither)', ...
          caller);
  end
  if isfield(model, 'rate_tau')
    if ~isnumeric(model.rate_tau) || ~isnumeric(model.rate_weight) || ...
       ~isreal(model.rate_tau) || ~isreal(model.rate_weight) || ...
       numel(model.rate_tau) ~= 1 || numel(model.rate_weight) ~= 1
      error('hyst:usage', '%s: rate_tau and rate_weight are real scalars', caller);
    end
    p.rate_tau = double(model.rate_tau);
    p.rate_weight = double(model.rate_weight);
  end
end

% SPDX-License-Identifier: MIT
function hyst_model_check(p, caller)
% HYST_MODEL_CHECK  The parts P of a model (HYST_MODEL_PARTS) as a model
% file and a header hold them: finite numbers, lo and hi scalars, for the
% asymmetric kind a degree 1..4 and degree (degree + 1) / 2 terms, for a
% grid 2..13 knots and K (K + 1) / 2 weights, for a spline 2..33 values
% and as many slopes, each >= 0 (f0 increases), a delay
% of whole samples, a creep term as a model file holds it (creep_tau and
% creep_weight both empty, or 1..4 numbers each, as many, the time
% constants at least 1 sample, all finite) and a rate term as a model file
% holds it (rate_tau and rate_weight both empty, or finite scalars, the
% time constant at least 1 sample). Another model raises hyst:usage. The curve itself (increasing, monotone) is the library's to
% check.
  if strcmp(p.kind, 'everett')
    numbers = [p.terms p.y_lo];
    if ~isscalar(p.degree) || ~any(p.degree == 1:4) || ...
       numel(p.terms) ~= p.degree * (p.degree + 1) / 2
      error('hyst:usage', '%s: degree is 1..4 and terms has degree (degree + 1) / 2 numbers', ...
            caller);
    end
  elseif strcmp(p.kind, 'everett_grid')
    numbers = [p.knots p.weights p.y_lo];
    k = numel(p.knots) - 1;
    if k < 1 || k > 12 || numel(p.weights) ~= k * (k + 1) / 2
      error('hyst:usage', '%s: knots has 2 to 13 numbers and weights K (K + 1) / 2 for K + 1 knots', ...
            caller);
    end
  elseif strcmp(p.kind, 'spline')
    numbers = [p.values p.slopes];
    k = numel(p.values) - 1;  % HYST_SPLINE_MAX_INTERVALS: 32
    if k < 1 || k > 32 || numel(p.slopes) ~= k + 1
      error('hyst:usage', '%s: values has 2 to 33 numbers (f0 at the knots) and slopes as many', ...
            caller);
    end
    if any(p.slopes < 0)  % as a model file's reader refuses it (NaN: below)
      error('hyst:usage', '%s: slopes: a slope is not >= 0 (f0 increases)', caller);
    end
  else
    numbers = p.coeffs;
  end
  if isempty(numbers) || ~isscalar(p.lo) || ~isscalar(p.hi) || ~all(isfinite([numbers p.lo p.hi]))
    error('hyst:usage', '%s: the model''s numbers must be finite, lo and hi scalars', caller);
  end
  if ~isscalar(p.delay) || ~isreal(p.delay) || ~(p.delay >= 0 && p.delay <= 1e9)
    error('hyst:usage', '%s: delay must be a delay of 0 to 1e9 samples (3.5: a sub-sample delay)', caller);
  end
  if numel(p.rate_tau) ~= numel(p.rate_weight) || numel(p.rate_tau) > 1 || ...
     ~all(isfinite([p.rate_tau p.rate_weight])) || ~all(p.rate_tau >= 1)
    error('hyst:usage', ['%s: rate_tau and rate_weight: one number each, the time constant ' ...
                         'at least 1 sample, finite (or both empty: no rate term)'], caller);
  end
  n = numel(p.creep_tau);
  if n ~= numel(p.creep_weight) || n > 4 || ~all(isfinite([p.creep_tau p.creep_weight])) || ...
     ~all(p.creep_tau >= 1)
    error('hyst:usage', ['%s: creep_tau and creep_weight: 1 to 4 numbers each, as many ' ...
                         '(one per creep term), time constants of at least 1 sample, finite ' ...
                         'weights (or both empty: no creep term)'], caller);
  end
end

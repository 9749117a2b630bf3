% SPDX-License-Identifier: MIT
function f = hyst_fit(x, y, varargin)
% HYST_FIT  Identifies a model (f0, or the asymmetric kind's E) from measured x, y.
%   F = HYST_FIT(X, Y) fits a cubic f0 to the record (X drive, Y measured
%   output) of a full-range periodic excitation, by hyst_ident_fit()
%   (include/hyst/ident.h, docs/identification.md). F is a model for
%   HYST_SIM, HYST_INV and HYST_MODEL_SAVE, with the fields
%     coeffs      f0's coefficients, highest power first (as polyfit)
%     lo, hi      the domain
%     rms, max_abs  residuals of the samples against the fitted major loop
%     used, rising, falling  samples used, by branch
%     increasing  true if f0 increases on [lo, hi] (else turn: where not)
%     degree, method
%
%   F = HYST_FIT(X, Y, 'kind', 'everett') fits the asymmetric kind's branch
%   function E of total degree 'degree' (1..4) by hyst_everett_fit_*: the
%   record starts from rest (lo) at sample 'skip', inputs outside the
%   domain are clamped as the model clamps them. 'tdegree' K (0..degree-1,
%   default degree-1: all terms) fits only the terms w^i t^j with j <= K,
%   the others 0: major loops alone determine E of t-degree 1 at most, at
%   any degree (a higher t-degree needs minor loops, else ERR_SINGULAR).
%   Fields:
%     kind        'everett'
%     degree, lo, hi, y_lo, terms  the model (HYST_SIM takes it)
%     t_degree    the highest power of t fitted
%     rms         residual of the least-squares fit
%     used        samples used
%     monotone    true if the library accepts E (else hyst_sim raises
%                 hyst:ERR_NOT_MONOTONE)
%
%   Options (name/value): 'kind' 'poly' (default) or 'everett', 'degree'
%   (default 3), 'skip' samples dropped at the start (default 0), 'delay'
%   samples the output lags the input (default 0), 'method' 'joint'
%   (default) or 'reflect' (kind poly), 'domain' [LO HI] (default: the
%   range of the inputs).
%   A library error raises hyst:<status name>, e.g. hyst:ERR_SINGULAR.
  opts = hyst_options(varargin, struct('kind', 'poly', 'degree', 3, 'skip', 0, 'delay', 0, ...
                                       'method', 'joint', 'domain', [], 'tdegree', []), ...
                      'hyst_fit');
  if ~isempty(opts.tdegree) && ~strcmp(opts.kind, 'everett')
    error('hyst:usage', 'hyst_fit: tdegree needs kind ''everett''');
  end
  switch lower(opts.method)
    case 'joint'
      method = 1;
    case 'reflect'
      method = 2;
    otherwise
      error('hyst:usage', 'hyst_fit: method is ''joint'' or ''reflect''');
  end
  if isempty(opts.domain)
    domain = [0 0];  % lo == hi: from the data
  elseif numel(opts.domain) == 2 && opts.domain(1) < opts.domain(2)
    domain = double(opts.domain);
  else
    error('hyst:usage', 'hyst_fit: domain is [LO HI] with LO < HI');
  end
  switch opts.kind
    case 'poly'
      f = hyst_mex('fit', double(x(:)), double(y(:)), double(opts.degree), method, ...
                   domain(1), domain(2), double(opts.skip), double(opts.delay));
      if ~f.increasing
        warning('hyst:not_increasing', ...
                'hyst_fit: the fitted f0 is not increasing on [%g, %g] (slope negative at %g): try another degree', ...
                f.lo, f.hi, f.turn);
      end
    case 'everett'
      tdegree = opts.tdegree;
      if isempty(tdegree)
        tdegree = opts.degree - 1;  % all of E's terms
      end
      f = hyst_mex('fit_everett', double(x(:)), double(y(:)), double(opts.degree), ...
                   domain(1), domain(2), double(opts.skip), double(opts.delay), ...
                   double(tdegree));
      if ~f.monotone
        warning('hyst:not_monotone', ...
                'hyst_fit: the fitted E is not increasing in a and decreasing in b on [%g, %g]: try another degree', ...
                f.lo, f.hi);
      end
    otherwise
      error('hyst:usage', 'hyst_fit: kind is ''poly'' or ''everett''');
  end
end

% SPDX-License-Identifier: MIT
function f = hyst_fit(x, y, varargin)
% HYST_FIT  Identifies a model (f0, or the asymmetric kind's E) from measured x, y.
%   F = HYST_FIT(X, Y) chooses the model of the record (X drive, Y measured
%   output) as 'hyst fit' with no option does: the kind, degree, delay and
%   creep term by hold-out (below, 'degree', []). F = HYST_FIT(X, Y,
%   'degree', N) fits f0 of degree N to a full-range periodic excitation by
%   hyst_ident_fit() (include/hyst/ident.h, docs/identification.md), its
%   delay chosen as 'hyst fit --degree N' chooses it unless 'delay' is
%   given; on a drive with minor loops such an f0, or one chosen among f0
%   alone ('kind', 'poly'), is biased (the estimator takes every sample
%   for a major branch's): warning hyst:minor_loops, as hyst fit warns. F
%   is a model for HYST_SIM, HYST_INV and HYST_MODEL_SAVE, with the fields
%     coeffs      f0's coefficients, highest power first (as polyfit)
%     lo, hi      the domain
%     rms, max_abs  residuals of the samples against the fitted major loop
%     used, rising, falling  samples used, by branch
%     increasing  true if f0 increases on [lo, hi] (else turn: where not)
%     degree, method
%     delay       the 'delay' it was fitted at (samples), which
%                 HYST_MODEL_SAVE writes to the model file
%     identified  (any kind but everett_grid, its domain wider than the
%                 inputs: a widened candidate chosen, or 'domain') [LO HI],
%                 the inputs' range it was identified on, saved with it
%
%   F = HYST_FIT(X, Y, 'kind', 'everett') fits the asymmetric kind's branch
%   function E of total degree 'degree' (1..4) by hyst_everett_fit_*: the
%   record starts from rest (lo) at sample 'skip', its outputs fitted from
%   the first input within 1 % of an end of the range on (every output
%   where that input comes after the first third), inputs outside the
%   domain clamped as the model clamps them. 'tdegree' K (0..degree-1,
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
%   F = HYST_FIT(X, Y, 'kind', 'everett_grid') fits the asymmetric kind on a
%   grid of 'degree' knot intervals (1..12) as 'hyst fit --kind
%   everett_grid' does (the knots where the output steps, the cells'
%   masses by least squares; no 'method', 'tdegree'): fields kind
%   'everett_grid', degree, lo, hi, y_lo, knots, weights (HYST_SIM takes
%   it), rms, max_abs, used, monotone (the library accepts the grid),
%   determined (false, with a warning hyst:undetermined, when the record's
%   turning points leave some masses open: major loops alone, for 4
%   intervals or more).
%
%   F = HYST_FIT(X, Y, 'kind', 'spline') fits the symmetric model whose f0
%   is a monotone cubic spline on 'degree' uniform knot intervals (1..32;
%   [] compares 2..16) as 'hyst fit --kind spline' does: f0 along every
%   branch, minor loops included (unbiased where a polynomial f0 is not),
%   continued over whole intervals to a 'domain' wider than the inputs as
%   'hyst fit --domain' continues it (no 'method'):
%   fields kind 'spline', lo, hi, values and slopes (f0 and its slope at
%   the knots lo + k (hi - lo) / intervals; HYST_SIM takes it), degree (the
%   intervals fitted), intervals (the model's), rms, max_abs, used,
%   increasing (the library accepts f0; else a warning
%   hyst:not_increasing). Compared with the other kinds without 'kind', as
%   'hyst fit' without --kind.
%
%   Options (name/value): 'kind' 'poly' (default with a degree),
%   'everett', 'everett_grid' or 'spline', 'degree' (default []: chosen), 'skip'
%   samples dropped at the start (default 0), 'delay' samples the output
%   lags the input (default []: chosen as hyst fit does, 0..8, or up to
%   1/64 of the drive's period, then a fraction of a sample: f.delay 12.5,
%   the model fitted on the drive interpolated), 'method' 'joint'
%   (default), 'reflect' or 'branches' (kind poly: E of t-degree 0, degree
%   1..4, fitted along every branch, minor loops included, and written as
%   f0, as 'hyst fit --method branches'), 'domain' [LO HI] (default: the
%   range of the inputs), 'creep' (below).
%
%   'degree', [] chooses the kind (the three compared, grids of 4 and 6
%   intervals among them, unless 'kind' is given),
%   the degree, the t-degree and, with 'delay', [], the delay by hold-out
%   with the hyst tool's own code ('hyst fit' without --degree; the Python
%   package's fit(degree=None) alike): F also has the field candidates, a
%   struct array of every candidate (kind, degree, t_degree, delay, params,
%   holdout_rms, fit_rms, status, creep_tau, creep_weight,
%   creep_holdout_rms, chosen, with_creep). The creep term is then the one
%   chosen with the model. An E of t-degree 0 chosen with kind poly
%   compared is the symmetric model: F is then its f0 as 'hyst fit' writes
%   it (coeffs in powers of x, method 'branches', everett the E: degree,
%   t_degree, y_lo, terms).
%
%   'creep' chooses a creep term as 'hyst fit --degree D --creep C' does
%   (docs/matlab.md, "Creep"): 'auto' (the default) fits the model on the
%   first two thirds of the record, runs it over all of it and fits one lag
%   of its input to its residual (its time constant the best of 100, 200,
%   500, ..., 20000 samples on the last third); the model gets it when the
%   model alone errs by more than 1 % more on the last third. 'none':
%   never; a number TAU (1..1e9): always a lag of TAU samples. The creep
%   term chosen gets its weight and a constant from the residual of the
%   model fitted on the whole record, the constant folded into the model
%   (f0's constant, E's y_lo, every one of a spline's values), and F the fields
%     creep_tau, creep_weight  the creep term (HYST_SIM, HYST_INV,
%                 HYST_MODEL_SAVE and HYST_HEADER take it)
%     creep       a struct: tau, weight, offset (folded in), rms and max_abs
%                 of the model with it over the record, holdout_rms with it
%                 and holdout_rms_without it on the last third
%   (none of them without a creep term). rms and max_abs stay the
%   hysteresis fit's own.
%
%   'rate' chooses a rate term (docs/rate.md) as 'hyst fit --rate R' does,
%   with 'degree', [] only: 'none' (the default), 'auto' (the choice scored
%   again with one of time constant 1 sample, 1/256 and 1/64 of the drive's
%   period, kept when it lowers the hold-out error by more than 1 %) or a
%   time constant TAU (1..1e9 samples, always). Its weight is fitted with
%   the creep lag's and the constant on the whole record; F then has the
%   fields rate_tau, rate_weight (HYST_SIM, HYST_INV, HYST_MODEL_SAVE and
%   HYST_HEADER take them) and rate (tau, weight, holdout_rms,
%   holdout_rms_without).
%
%   'validate', [X2 Y2] (a second record of the same actuator, its drive
%   and output as two columns: validation data, as 'hyst fit --validate')
%   makes every choice above (kind, degree, delay, creep, rate) on it
%   instead of the hold-out: each candidate fitted on the whole of X, Y
%   from 'skip' on and scored by its RMS error run from rest over X2, Y2
%   from 'skip' on (the candidates' holdout_rms is that error). F then has
%   the field validation_rms, the model's error there, and excitation says
%   what X2 tests the choice on. The record is refused as X, Y are.
%   A library error raises hyst:<status name>, e.g. hyst:ERR_SINGULAR.
  opts = hyst_options(varargin, struct('kind', '', 'degree', [], 'skip', 0, 'delay', [], ...
                                       'method', 'joint', 'domain', [], 'tdegree', [], ...
                                       'creep', 'auto', 'rate', 'none', 'validate', []), ...
                      'hyst_fit');
  kinds = 15;  % the choice compares the four kinds unless 'kind' names one
  if isempty(opts.kind)
    opts.kind = 'poly';
  elseif ischar(opts.kind)
    kinds = kind_code(opts.kind);
  end
  if ~isempty(opts.tdegree) && ~strcmp(opts.kind, 'everett')
    error('hyst:usage', 'hyst_fit: tdegree needs kind ''everett''');
  end
  branches = false;  % f0 fitted along every branch: E of t-degree 0, written as f0
  switch lower(opts.method)
    case 'joint'
      method = 1;
    case 'reflect'
      method = 2;
    case 'branches'
      method = 1;
      branches = true;
    otherwise
      error('hyst:usage', 'hyst_fit: method is ''joint'', ''reflect'' or ''branches''');
  end
  if isempty(opts.domain)
    domain = [0 0];  % lo == hi: from the data
  elseif numel(opts.domain) == 2 && opts.domain(1) < opts.domain(2)
    domain = double(opts.domain);
  else
    error('hyst:usage', 'hyst_fit: domain is [LO HI] with LO < HI');
  end
  if ~ischar(opts.kind) || ~any(strcmp(opts.kind, {'poly', 'everett', 'everett_grid', 'spline'}))
    error('hyst:usage', 'hyst_fit: kind is ''poly'', ''everett'', ''everett_grid'' or ''spline''');
  end
  creep_tau = creep_option(opts.creep, 'creep');
  rate_tau = creep_option(opts.rate, 'rate');
  if rate_tau >= 0 && ~isempty(opts.degree)
    error('hyst:usage', ['hyst_fit: ''rate'' applies to the automatic choice (''degree'', []), ' ...
                         'as hyst fit --rate']);
  end
  if branches
    if ~strcmp(opts.kind, 'poly')
      error('hyst:usage', ['hyst_fit: method ''branches'' fits kind ''poly'' (f0 along every ' ...
                           'branch), not kind ''%s'''], opts.kind);
    end
    config = hyst_mex('config');
    if ~isempty(opts.degree) && opts.degree > config.everett_max_degree
      error('hyst:usage', ['hyst_fit: method ''branches'' fits f0 of degree 1..%d (E of ' ...
                           't-degree 0), not %d'], config.everett_max_degree, opts.degree);
    end
    opts.kind = 'everett';
    opts.tdegree = 0;
    kinds = 2;
  end
  x = double(x(:));
  y = double(y(:));
  rec = check_record(x, y, opts);
  % f0 of a given degree, or chosen among f0 alone, on a drive with minor
  % loops: warned of below
  degree_given = ~isempty(opts.degree);
  minor_loops = strcmp(opts.kind, 'poly') && (degree_given || kinds == 1) && rec.minor > 0;
  vx = zeros(0, 1);  % the validation record (empty: the hold-out)
  vy = zeros(0, 1);
  if ~isempty(opts.validate)
    if ~(isnumeric(opts.validate) && isreal(opts.validate) && ismatrix(opts.validate) && ...
         size(opts.validate, 2) == 2)
      error('hyst:usage', 'hyst_fit: validate is a record [X2 Y2] of two columns');
    end
    vx = double(opts.validate(:, 1));
    vy = double(opts.validate(:, 2));
    if numel(vx) < double(opts.skip) + 2
      error('hyst:usage', ['hyst_fit: validate: %d samples after skip %d: a validation ' ...
                           'record needs two or more'], max(numel(vx) - double(opts.skip), 0), ...
            double(opts.skip));
    end
    vopts = opts;
    vopts.delay = [];
    check_record(vx, vy, vopts, {'validate''s X2', 'validate''s Y2'});
  end
  cands = [];
  fraction = 0;  % a sub-sample delay chosen: the drive x interpolated by it
  rate = struct('with_rate', false);  % a rate term chosen with the model
  if isempty(opts.degree)
    [opts, cands, creep_tau, domain, x, fraction, rate, vx] = choose(opts, kinds, method, ...
                                                                     domain, x, y, creep_tau, ...
                                                                     rate_tau, vx, vy);
  elseif isempty(opts.delay)
    % the delay of the model given, as 'hyst fit --degree D' without --delay
    % chooses it (the gateway's given_delay: fit_given_delay())
    tk = 0;
    if strcmp(opts.kind, 'everett')
      tk = opts.degree - 1;
      if ~isempty(opts.tdegree)
        tk = opts.tdegree;
      end
    end
    [opts.delay, fraction, x, vxf] = hyst_mex('given_delay', x, y, kind_code(opts.kind), ...
                                              double(opts.degree), double(tk), method, ...
                                              domain(1), domain(2), double(opts.skip), vx, vy);
    if ~isempty(vx)
      vx = vxf;  % interpolated by the fraction as x is
    end
  end
  tdegree = opts.tdegree;
  if isempty(tdegree)
    tdegree = opts.degree - 1;  % all of E's terms
  end
  f = fit_part(opts, method, domain, tdegree, x, y);
  if ~isempty(cands)
    f.candidates = cands;
    f.excitation = excitation(x, y, double(opts.skip), numel(x) - double(opts.delay), ...
                              double(opts.delay), vx, vy);
  end
  % the delay the model was fitted at: HYST_MODEL_SAVE writes it,
  % HYST_HEADER states it
  f.delay = double(opts.delay) + fraction;
  % a domain wider than the inputs: the range f0 (or E) was identified
  % on, which HYST_MODEL_SAVE records (as 'hyst fit --save' does)
  used = x(double(opts.skip) + 1:max(numel(x) - double(opts.delay), double(opts.skip)));
  if ~strcmp(opts.kind, 'everett_grid') && ~isempty(used) && ...
     (f.lo < min(used) || max(used) < f.hi)
    f.identified = [max(min(used), f.lo), min(max(used), f.hi)];
  end
  if minor_loops
    if ~degree_given
      what = 'of every degree';
      leave = 'out ''kind'' to let hyst_fit compare E too';
    else
      what = sprintf('of degree %d', opts.degree);
      leave = '''degree'' [] to let hyst_fit choose';
    end
    warning('hyst:minor_loops', ['hyst_fit: x has %d reversal%s inside its range (minor ' ...
                                 'loops): f0 %s is biased, its fit taking every rising ' ...
                                 'sample for the major ascending branch and every falling ' ...
                                 'one for the descending; leave %s, or fit ''method'', ' ...
                                 '''branches'' (f0 along every branch)'], rec.minor, ...
                                 repmat('s', 1, rec.minor ~= 1), ...
            what, leave);
  end
  if strcmp(opts.kind, 'poly') && ~f.increasing
    warning('hyst:not_increasing', ...
            'hyst_fit: the fitted f0 is not increasing on [%g, %g] (slope negative at %g): try another degree', ...
            f.lo, f.hi, f.turn);
  elseif strcmp(opts.kind, 'everett') && ~f.monotone
    warning('hyst:not_monotone', ...
            'hyst_fit: the fitted E is not increasing in a and decreasing in b on [%g, %g]: try another degree', ...
            f.lo, f.hi);
  elseif strcmp(opts.kind, 'everett_grid') && ~f.monotone
    warning('hyst:not_monotone', ...
            'hyst_fit: the library refuses the fitted grid on [%g, %g]: try another number of intervals', ...
            f.lo, f.hi);
  elseif strcmp(opts.kind, 'spline') && ~f.increasing
    warning('hyst:not_increasing', ...
            'hyst_fit: the library refuses the fitted spline f0 on [%g, %g]: try another number of intervals', ...
            f.lo, f.hi);
  end
  if strcmp(opts.kind, 'everett_grid')
    if ~f.determined
      warning('hyst:undetermined', 'hyst_fit: %s', f.undetermined_why);
    end
    f = rmfield(f, 'undetermined_why');
  end
  f = with_terms(f, opts, method, domain, tdegree, x, y, creep_tau, rate, vx, vy);
  % E of t-degree 0 is the symmetric model: written as f0, as hyst fit writes it
  if branches || (~isempty(cands) && strcmp(opts.kind, 'everett') && tdegree == 0 && ...
                  bitand(kinds, 1))
    f = written_as_poly(f);
    if branches && ~isfield(f, 'everett') && f.monotone
      error('hyst:usage', ['hyst_fit: method ''branches'': E of degree %d fitted along the ' ...
                           'branches gives no f0 in powers of x on [%.9g, %.9g] (they cancel ' ...
                           'far from 0, or f0 falls): shift the inputs, or fit ''kind'', ' ...
                           '''everett'', ''tdegree'', 0'], f.degree, f.lo, f.hi);
    end
  end
end

function f = with_terms(f, opts, method, domain, tdegree, x, y, creep_tau, rate, vx, vy)
% The creep and rate terms chosen with the model f, fitted on the whole
% record (none: f as it is).
  skip = double(opts.skip);
  delay = double(opts.delay);
  if numel(x) <= skip + delay || ~usable(f)
    return;
  end
  % the creep term scored by hold-out as hyst fit scores it (the gateway's
  % score: fit_score() of tools/cli/fit_select.c, the hold-out splits)
  c = [];
  without = NaN;
  if creep_tau >= 0 || ~isempty(vx)  % on a validation record, the model scored there too
    if any(strcmp(opts.kind, {'everett_grid', 'spline'}))  % degree: their intervals
      tdegree = 0;
    end
    [without, c] = hyst_mex('score', x, y, kind_code(opts.kind), double(opts.degree), ...
                            double(tdegree), method, domain(1), domain(2), skip, delay, ...
                            creep_tau, vx, vy);
    config = hyst_mex('config');  % fit_parsimony: hyst fit's margin
    if creep_tau < 0 || ~isfinite(without) || isempty(c) || ~(c.tau > 0) || ...
       ~isfinite(c.holdout_rms) || ...
       (creep_tau == 0 && without <= c.holdout_rms * (1 + config.fit_parsimony))
      c = [];
    end
    if ~isempty(vx)  % the model's error on it, with the terms it has
      f.validation_rms = without;
      if rate.with_rate
        f.validation_rms = rate.holdout_rms;
      elseif ~isempty(c)
        f.validation_rms = c.holdout_rms;
      end
    end
  end
  if isempty(c) && ~rate.with_rate
    return;
  end
  % the weights and a constant fitted to the residual of the model fitted on
  % the whole record (no hold-out), the constant folded into the model
  tau = -1;
  if ~isempty(c)
    tau = c.tau;
  end
  rate_tau = 0;
  if rate.with_rate
    rate_tau = rate.rate_tau;
  end
  [~, cf] = holdout(f, x, y, skip, delay, numel(x) - delay, tau, rate_tau);
  if isempty(cf) || ~isfinite(cf.weight) || ~isfinite(cf.offset) || ...
     (rate_tau > 0 && ~isfinite(cf.rate_weight))
    what = 'creep';
    if isempty(c)
      what = 'rate';
      tau = rate_tau;
    end
    error('hyst:creep', ['hyst_fit: the %s term of time constant %g samples could not be ' ...
                         'fitted to the model''s residual (a drive that never moves?)'], what, tau);
  end
  if any(strcmp(opts.kind, {'everett', 'everett_grid'}))
    f.y_lo = f.y_lo + cf.offset;
  elseif strcmp(opts.kind, 'spline')  % f0 moved as a whole, as hyst fit moves it
    f.values = f.values + cf.offset;
  else
    f.coeffs(end) = f.coeffs(end) + cf.offset;
  end
  if ~isempty(c)
    f.creep_tau = cf.tau;
    f.creep_weight = cf.weight;
    f.creep = struct('tau', cf.tau, 'weight', cf.weight, 'offset', cf.offset, 'rms', cf.fit_rms, ...
                     'max_abs', cf.max_abs, 'holdout_rms', c.holdout_rms, ...
                     'holdout_rms_without', without);
  end
  if rate_tau > 0
    f.rate_tau = cf.rate_tau;
    f.rate_weight = cf.rate_weight;
    f.rate = struct('tau', cf.rate_tau, 'weight', cf.rate_weight, ...
                    'holdout_rms', rate.holdout_rms, 'holdout_rms_without', rate.without);
  end
end

function [opts, cands, creep_tau, domain, x, fraction, rate, vx] = choose(opts, kinds, ...
                                                                         method, domain, x, ...
                                                                         y, creep_tau, ...
                                                                         rate_tau, vx, vy)
% The kind, degree, t-degree and delay (and whether with a creep term)
% chosen by hold-out with the hyst tool's own code (the gateway's select:
% fit_search() of tools/cli/fit_select.c), as 'hyst fit' without --degree
% and the Python package's fit(degree=None) choose: with 'delay', [] the
% delays scaled to the drive and a fraction of a sample (x is then the
% drive interpolated by it, which the model is fitted on). rate: the rate
% term scored on the choice's hold-out as hyst fit --rate scores it
% (rate_tau: -1 none, 0 auto, > 0 that time constant). vx, vy: a
% validation record every candidate is scored on instead (empty: the
% hold-out), vx returned interpolated as x is.
  delay = -1;  % chosen
  if ~isempty(opts.delay)
    delay = double(opts.delay);
  end
  tdegree = -1;
  if ~isempty(opts.tdegree)
    tdegree = double(opts.tdegree);
  end
  [cands, best, with_creep, widened, fraction, xf, rate, vxf] = ...
      hyst_mex('select', x, y, kinds, method, domain(1), domain(2), double(opts.skip), delay, ...
               tdegree, creep_tau, rate_tau, vx, vy);
  if fraction > 0
    x = xf;
    if ~isempty(vx)
      vx = vxf;
    end
  end
  if best == 0
    what = 'the last third of the record';
    if ~isempty(vx)
      what = 'the validation record';
    end
    error('hyst:no_candidate', ['hyst_fit: no candidate gave a model (an increasing f0, a ' ...
                                'monotone E, a spline f0 the library accepts) that could ' ...
                                'predict %s'], what);
  end
  for k = 1:numel(cands)
    cands(k).chosen = k == best;
    cands(k).with_creep = k == best && with_creep;
  end
  c = cands(best);
  opts.kind = c.kind;
  opts.degree = c.degree;
  opts.delay = c.delay;
  opts.tdegree = c.t_degree;
  if ~isempty(widened)
    % the domain the tool fits it on: the inputs' range widened, f0
    % or E continued beyond the inputs (fit_chosen_domain())
    domain = widened;
  end
  % the creep term chosen with it, or none: fitted below as 'creep', TAU does
  creep_tau = -1;
  if with_creep
    creep_tau = c.creep_tau;
  end
end

function f = written_as_poly(f)
% The chosen E of t-degree 0 (its creep term's offset in y_lo) as the model
% it is, the symmetric one, whose compensator is a table: f0 in powers of
% x (hyst fit's fit_poly_from_everett()), method 'branches' and everett
% the E it was fitted as; f itself where that refuses it.
  if ~f.monotone
    return;
  end
  coeffs = hyst_mex('poly_from_everett', f.degree, f.lo, f.hi, f.y_lo, f.terms);
  if isempty(coeffs)
    return;
  end
  e = struct('degree', f.degree, 't_degree', f.t_degree, 'y_lo', f.y_lo, 'terms', f.terms);
  f = rmfield(f, {'kind', 't_degree', 'y_lo', 'terms', 'monotone'});
  f.coeffs = coeffs;
  f.method = 'branches';
  f.increasing = true;
  f.everett = e;
end

function f = fit_part(opts, method, domain, tdegree, x, y)
% The library's fit of the model to the samples x, y (a record's start, or all of it).
  if strcmp(opts.kind, 'poly')
    f = hyst_mex('fit', x, y, double(opts.degree), method, domain(1), domain(2), ...
                 double(opts.skip), double(opts.delay));
  elseif any(strcmp(opts.kind, {'everett_grid', 'spline'}))  % 'degree': the intervals
    command = struct('everett_grid', 'fit_grid', 'spline', 'fit_spline');
    f = hyst_mex(command.(opts.kind), x, y, double(opts.degree), domain(1), domain(2), ...
                 double(opts.skip), double(opts.delay));
  else
    f = hyst_mex('fit_everett', x, y, double(opts.degree), domain(1), domain(2), ...
                 double(opts.skip), double(opts.delay), double(tdegree));
  end
end

function ok = usable(f)
% f0 increasing, or E accepted by the library: a model that runs.
  if isfield(f, 'kind') && any(strcmp(f.kind, {'everett', 'everett_grid'}))
    ok = f.monotone;
  else
    ok = f.increasing;
  end
end

function [rms, c] = holdout(f, x, y, skip, delay, from, tau, rate_tau)
% The model f run from rest over the record as hyst fit scores it (the
% gateway's holdout: its RMS error from sample from + 1 on), and the creep
% term of time constant tau (0: the best of hyst fit's series; < 0: none)
% and the rate term of time constant rate_tau (0: none) fitted to its
% residual before that sample and scored after.
  if nargin < 8
    rate_tau = 0;
  end
  [suffix, args] = hyst_model_args(hyst_model_parts(f, 'hyst_fit'));
  [rms, c] = hyst_mex(['holdout' suffix], args{:}, x, y, skip, delay, from, tau, rate_tau);
end

function code = kind_code(kind)
% The kind as the gateway's select and score take it (fit_select.h's
% FIT_POLY 1, FIT_EVERETT 2, FIT_GRID 4, FIT_SPLINE 8).
  code = 1 + strcmp(kind, 'everett') + 3 * strcmp(kind, 'everett_grid') + 7 * strcmp(kind, 'spline');
end

function tau = creep_option(c, what)
% 'creep' ('rate') as hyst fit's --creep (--rate): -1 none, 0 auto, or the time constant.
  if ischar(c) && any(strcmp(c, {'none', 'auto'}))
    tau = -double(strcmp(c, 'none'));
  elseif isnumeric(c) && isscalar(c) && isreal(c) && c >= 1 && c <= 1e9
    tau = double(c);
  else
    error('hyst:usage', ['hyst_fit: ''%s'' is ''none'', ''auto'' or a time constant of ' ...
                         '1 to 1e9 samples'], what);
  end
end

% The record as 'hyst fit' takes a file: NaN marks a missing sample; an
% infinite one, skip or delay not a whole number >= 0, a column that does
% not vary or a response that falls as the drive rises is refused
% (hyst:usage), naming it (names: the two columns' names, default x and
% y), by hyst fit's check (the gateway's record_check: fit_record_check());
% none left is the library's ERR_ARG, as x and y of different lengths are
% (the gateway's). rec: the check (its minor: the drive's reversals inside
% its range).
function rec = check_record(x, y, opts, names)
  if nargin < 4
    names = {'x', 'y'};
  end
  if ~(hyst_is_whole(opts.skip) && opts.skip >= 0)
    error('hyst:usage', 'hyst_fit: skip must be a whole number of samples >= 0');
  end
  delay = 0;
  if ~isempty(opts.delay)
    if ~(hyst_is_whole(opts.delay) && opts.delay >= 0)
      error('hyst:usage', 'hyst_fit: delay must be a whole number of samples >= 0');
    end
    delay = double(opts.delay);
  end
  skip = double(opts.skip);
  rec = hyst_mex('record_check', x, y, skip, delay);
  switch rec.fault
    case {'infinite_input', 'infinite_output'}
      error('hyst:usage', ['hyst_fit: %s(%d) is %g: a record''s samples are finite numbers, ' ...
                           'or NaN where one is missing'], ...
            names{1 + strcmp(rec.fault, 'infinite_output')}, rec.at, rec.value);
    case 'no_sample'
      error('hyst:ERR_ARG', 'hyst_fit: skip %d and delay %d leave no sample of the %d given', ...
            skip, delay, numel(x));
    case 'constant_input'
      error('hyst:usage', 'hyst_fit: %s is constant (NaN aside): a record''s drive must vary', ...
            names{1});
    case 'constant_output'
      error('hyst:usage', ['hyst_fit: %s is constant (NaN aside): a record''s response must ' ...
                           'vary'], names{2});
    case 'falling'
      % every model of hyst rises with its input (a sensor of the opposite
      % sign, as hyst fit says)
      error('hyst:usage', ['hyst_fit: %s falls as %s rises (correlation %.3g): every model ' ...
                           'of hyst rises with its input; negate %s'], names{2}, names{1}, ...
            rec.correlation, names{2});
  end
end

% What the hold-out's last third tested the automatic choice on (the
% gateway's excitation: fit_holdout_excitation(), as 'hyst fit' prints it),
% with hyst fit's warnings (hyst:excitation).
function e = excitation(x, y, skip, finish, delay, vx, vy)
  if isempty(vx)
    e = hyst_mex('excitation', x, y, skip, finish, delay);
    part = {'the last third''s', 'the record''s range', 'the last third', 'the inputs'' range'};
  else  % what the validation record tests it on
    e = hyst_mex('excitation', x, y, skip, finish, delay, vx, vy);
    part = {'the validation record''s', 'the range of the record''s', 'the validation record', ...
            'the record''s inputs'' range or beyond'};
  end
  if e.span < e.min_span
    warning('hyst:excitation', ['hyst_fit: %s inputs span %.3g %% of %s: the choice was not ' ...
                                'tested over the rest of it'], part{1}, 100 * e.span, part{2});
  end
  if e.minor == 0
    warning('hyst:excitation', ['hyst_fit: %s holds no minor loop (every reversal at an end ' ...
                                'of %s): the choice was not tested on minor loops'], ...
            part{3}, part{4});
  end
  e = rmfield(e, 'min_span');
end

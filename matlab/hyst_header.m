% SPDX-License-Identifier: MIT
function text = hyst_header(model, name, varargin)
% HYST_HEADER  The C header that gives firmware a model, and its compensator's table.
%   TEXT = HYST_HEADER(MODEL, NAME) returns the text of NAME.h as the host
%   tool writes it (hyst header --model FILE NAME, docs/cli.md), but for its
%   first line, which names the generator: for a polynomial f0
%   'static const hyst_poly_t NAME = {...};' (firmware: hyst_init(&S, &NAME,
%   ...)), for a model of kind 'everett' 'static const hyst_everett_t NAME =
%   {...};' (hyst_curve_from_everett(), then hyst_init_kind()), for kind
%   'everett_grid' a hyst_everett_grid_t and for kind 'spline' a
%   hyst_spline_t (hyst_curve_from_everett_grid(),
%   hyst_curve_from_spline(): their tables' lengths in a comment), the numbers
%   as 17-digit literals in HYST_REAL_C(), exact in a double build. MODEL is
%   a struct as HYST_SIM and HYST_MODEL_SAVE take it (an E the library
%   refuses, hyst_curve_from_everett(), is refused here); its delay, when it
%   has one, is stated in a comment. NAME is a C identifier.
%
%   HYST_HEADER(MODEL, NAME, 'compensator', true) adds the compensator's
%   table, built here by the library in float and in double (the float one
%   from the model's numbers as a float build reads them) and sealed:
%   NAME_table and NAME_seal of the build's real type (HYST_USE_DOUBLE),
%   NAME_INTERVALS (and NAME_ROWS), for hyst_curve_inverse_table_const() (a
%   polynomial f0) or hyst_curve_everett_inverse_table_const() (kind
%   everett): firmware takes the table from flash instead of building it at
%   init. 'intervals', N (1..2^20; default HYST_INV_TABLE, 256, or for kind
%   everett HYST_EVERETT_INV_INTERVALS, 32) and, for kind everett only,
%   'rows', R (3..4096; default HYST_EVERETT_INV_ROWS, 16) size the table;
%   they need 'compensator', true. Kind everett_grid has no table (its
%   compensator, hyst_curve_everett_grid_inverse(), solves each branch):
%   the header says so, 'intervals' and 'rows' are refused. Kind spline has
%   none without 'intervals' (hyst_curve_spline_inverse() solves each
%   sample: the header says so); with 'intervals', N the table firmware
%   builds at init (hyst_curve_spline_inverse_table(), no table from
%   flash), measured here: NAME_INTERVALS and the calls.
%
%   A model with a creep term (fields creep_tau, creep_weight) also gets
%   '#include "hyst/creep.h"' and, after its declaration, NAME_CREEP_TERMS,
%   NAME_creep_tau and NAME_creep_weight (hyst_wide_t arrays of HYST_REAL_C()
%   literals) for hyst_creep_init(&creep, NAME_CREEP_TERMS, NAME_creep_tau,
%   NAME_creep_weight, lo), as the host tool writes them; the compensator's
%   table is the hysteresis model's alone (firmware subtracts
%   hyst_creep_output() from the desired output before it). A model with a
%   rate term (fields rate_tau, rate_weight) also gets '#include
%   "hyst/rate.h"', NAME_rate_tau and NAME_rate_weight, for
%   hyst_rate_init(&rate, NAME_rate_tau, NAME_rate_weight, lo).
%
%   HYST_HEADER(..., 'file', F) also writes TEXT to the file F, whole or not
%   at all: a temporary file beside F, renamed to F once written; on failure
%   it is removed and an error hyst:model_file raised.
  caller = 'hyst_header';
  opts = hyst_options(varargin, struct('compensator', false, 'intervals', [], 'rows', [], ...
                                       'file', []), caller);
  p = hyst_model_parts(model, caller);
  hyst_model_check(p, caller);
  if ~ischar(name) || size(name, 1) ~= 1 || isempty(name) || numel(name) >= 200 || ...
     ~all(ismember(name, ['A':'Z' 'a':'z' '0':'9' '_'])) || any(name(1) == '0':'9')
    error('hyst:usage', ['%s: NAME must be a C identifier (a letter or _, then letters, ' ...
                         'digits, _)'], caller);
  end
  c = opts.compensator;
  if ~isscalar(c) || ~(islogical(c) || (isnumeric(c) && (c == 0 || c == 1)))
    error('hyst:usage', '%s: ''compensator'' is true or false', caller);
  end
  if ~c && ~(isempty(opts.intervals) && isempty(opts.rows))
    error('hyst:usage', ['%s: ''intervals'' and ''rows'' size the compensator''s table: ' ...
                         'they need ''compensator'', true'], caller);
  end
  if ~isempty(opts.file) && (~ischar(opts.file) || size(opts.file, 1) ~= 1)
    error('hyst:usage', '%s: ''file'' is a file name', caller);
  end
  config = hyst_mex('config');
  if strcmp(p.kind, 'poly') && (numel(p.coeffs) < 2 || numel(p.coeffs) > config.max_degree + 1)
    error('hyst:usage', '%s: coeffs has 2 to %d numbers (degree 1..HYST_MAX_DEGREE)', caller, ...
          config.max_degree + 1);
  end
  % a grid's compensator is solved: it needs no table; a spline's is solved
  % unless 'intervals' tabulates it
  solved = hyst_solved_compensator(p.kind);
  if ~isempty(solved) && c && (~isempty(opts.intervals) || ~isempty(opts.rows))
    error('hyst:usage', '%s: kind %s has no compensator table (its compensator %s)', caller, ...
          p.kind, solved);
  end
  tabled = c && isempty(solved) && ...
           (~strcmp(p.kind, 'spline') || ~isempty(opts.intervals) || ~isempty(opts.rows));
  check_curve(p, caller);
  % the guard, the declaration and the creep term (and the compensator's
  % table: the library builds it in float and in double, sealed): the
  % format's one implementation (tools/model_text), as 'hyst header' writes them
  parts = hyst_text_parts(p);
  table = '';
  if tabled
    [intervals, rows] = hyst_table_sizes(opts.intervals, opts.rows, p.kind, caller, false);
    table = hyst_mex('header_table', name, parts{:}, intervals, rows);
  end
  text = [model_comment(p, c && ~tabled), hyst_mex('header_open', name, parts{:}, p.rate_tau, p.rate_weight), ...
          table, ...
          hyst_mex('header_close', name)];
  if ~isempty(opts.file)
    hyst_write_whole(opts.file, text, caller);
  end
end

function check_curve(p, caller)
% The curve as firmware's init would take it (f0, E, the grid or the
% spline: the library's curve checks, then its init), as the host tool
% checks it: the gateway inits it and runs no sample.
  [suffix, args] = hyst_model_args(p);
  try
    hyst_mex(['sim' suffix], args{:}, zeros(0, 1), 2, 0);
  catch err
    error(err.identifier, '%s: the model is refused: %s', caller, err.message);
  end
end

function text = model_comment(p, compensator)
% The first comment: the generator (its first line, the one that differs
% from the host tool's), the model, the sensor's delay (a grid's or a
% spline's compensator: how firmware builds it).
  first = ['/* Generated by the MATLAB/Octave package hyst (hyst_header), as ''hyst header'' ' ...
           'writes it:\n'];
  if any(strcmp(p.kind, {'everett_grid', 'spline'}))
    if strcmp(p.kind, 'spline')
      what = {'symmetric model, f0 a monotone cubic spline\n *', numel(p.values) - 1, ...
              'hyst_curve_from_spline()', 'hyst_kind_spline'};
    else
      what = {'asymmetric model on a grid', numel(p.knots) - 1, 'hyst_curve_from_everett_grid()', ...
              'hyst_kind_everett_grid'};
    end
    text = sprintf([first ...
                    ' * ' what{1} ' of %d knot intervals on [%.9g, %.9g]\n' ...
                    ' * (%s, then\n' ...
                    ' * hyst_init_kind() with %s); the\n' ...
                    ' * measured output follows its input %.17g samples later (a sensor\n' ...
                    ' * delay: the model does not include it).%s */\n'], what{2}, ...
                   p.lo, p.hi, what{3}, what{4}, p.delay, solved_compensator(p.kind, compensator));
  elseif strcmp(p.kind, 'everett')
    text = sprintf([first ...
                    ' * asymmetric model, branch function E of degree %d on [%.9g, %.9g]\n' ...
                    ' * (hyst_curve_from_everett(), then hyst_init_kind() with\n' ...
                    ' * hyst_kind_everett); the measured\n' ...
                    ' * output follows its input %.17g samples later (a sensor delay: the\n' ...
                    ' * model does not include it). */\n'], p.degree, p.lo, p.hi, p.delay);
  else
    text = sprintf([first ...
                    ' * f0 of degree %d on [%.9g, %.9g]; the measured output follows its input\n' ...
                    ' * %.17g samples later (a sensor delay: the model does not include it). */\n'], ...
                   numel(p.coeffs) - 1, p.lo, p.hi, p.delay);
  end
end

function text = solved_compensator(kind, compensator)
% A grid's or a spline's header's sentence on its compensator, as 'hyst
% header --compensator' writes it.
  text = '';
  if compensator && strcmp(kind, 'spline')
    text = sprintf(['\n * The compensator: hyst_curve_spline_inverse() of that curve,\n' ...
                    ' * then hyst_init_kind() with hyst_kind_spline; each drive solved on\n' ...
                    ' * its cubic piece per sample, no table of its own.']);
  elseif compensator
    text = sprintf(['\n * The compensator: hyst_curve_everett_grid_inverse() of that curve,\n' ...
                    ' * then hyst_init_kind() with hyst_kind_everett_grid_inverse; each\n' ...
                    ' * branch solved in closed form, no table of its own.']);
  end
end

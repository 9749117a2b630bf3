% SPDX-License-Identifier: MIT
function text = hyst_header(model, name, varargin)
% HYST_HEADER  The C header that gives firmware a model, and its compensator's table.
%   TEXT = HYST_HEADER(MODEL, NAME) returns the text of NAME.h as the host
%   tool writes it (hyst header --model FILE NAME, docs/cli.md), but for its
%   first line, which names the generator: for a polynomial f0
%   'static const hyst_poly_t NAME = {...};' (firmware: hyst_init(&S, &NAME,
%   ...)), for a model of kind 'everett' 'static const hyst_everett_t NAME =
%   {...};' (hyst_curve_from_everett(), then hyst_init_curve()), the numbers
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
%   they need 'compensator', true.
%
%   A model with a creep term (fields creep_tau, creep_weight) also gets
%   '#include "hyst/creep.h"' and, after its declaration, NAME_CREEP_TERMS,
%   NAME_creep_tau and NAME_creep_weight (hyst_wide_t arrays of HYST_REAL_C()
%   literals) for hyst_creep_init(&creep, NAME_CREEP_TERMS, NAME_creep_tau,
%   NAME_creep_weight, lo), as the host tool writes them; the compensator's
%   table is the hysteresis model's alone (firmware subtracts
%   hyst_creep_output() from the desired output before it).
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
  if strcmp(p.kind, 'everett')
    check_everett(p, caller);
  end
  table = '';
  if c
    [intervals, rows] = hyst_table_sizes(opts.intervals, opts.rows, p.kind, caller, false);
    table = compensator_text(p, name, intervals, rows);
  end
  guard = [upper(name) '_H'];
  includes = sprintf('#include "hyst/curve.h"\n');
  if ~isempty(p.creep_tau)
    includes = [includes sprintf('#include "hyst/creep.h"\n')];
  end
  text = [model_comment(p), sprintf('#ifndef %s\n#define %s\n\n%s\n', guard, guard, includes), ...
          declaration(p, name), creep_text(p, name), table, sprintf('\n#endif /* %s */\n', guard)];
  if ~isempty(opts.file)
    hyst_write_whole(opts.file, text, caller);
  end
end

function check_everett(p, caller)
% E as firmware's init would take it (hyst_f64_curve_from_everett(), then
% hyst_f64_init_curve()), as the host tool checks it: the gateway inits it
% and runs no sample.
  try
    hyst_mex('sim_everett', p.degree, p.lo, p.hi, p.y_lo, p.terms, zeros(0, 1), 2, 0);
  catch err
    error(err.identifier, '%s: the model is refused: %s', caller, err.message);
  end
end

function text = model_comment(p)
% The first comment: the generator (its first line, the one that differs
% from the host tool's), the model, the sensor's delay.
  first = ['/* Generated by the MATLAB/Octave package hyst (hyst_header), as ''hyst header'' ' ...
           'writes it:\n'];
  if strcmp(p.kind, 'everett')
    text = sprintf([first ...
                    ' * asymmetric model, branch function E of degree %d on [%.9g, %.9g]\n' ...
                    ' * (hyst_curve_from_everett(), then hyst_init_curve()); the measured\n' ...
                    ' * output follows its input %d samples later (a sensor delay: the\n' ...
                    ' * model does not include it). */\n'], p.degree, p.lo, p.hi, p.delay);
  else
    text = sprintf([first ...
                    ' * f0 of degree %d on [%.9g, %.9g]; the measured output follows its input\n' ...
                    ' * %d samples later (a sensor delay: the model does not include it). */\n'], ...
                   numel(p.coeffs) - 1, p.lo, p.hi, p.delay);
  end
end

function text = declaration(p, name)
% 'static const hyst_poly_t NAME = {...};' or, for kind everett, 'static
% const hyst_everett_t NAME = {...};' with every row of e[][] written out
% (zeros above the degree: no brace is elided), as the host tool writes them.
  lit = @(v) strcat('HYST_REAL_C(', c_numbers(v, 17), ')');
  if strcmp(p.kind, 'everett')
    n = 4;                            % HYST_EVERETT_MAX_DEGREE
    e = zeros(n, n);
    k = 1;
    for i = 1:p.degree
      for j = 0:p.degree - i
        e(i, j + 1) = p.terms(k);
        k = k + 1;
      end
    end
    rows = cell(1, n);
    for i = 1:n
      rows{i} = ['{' strjoin(lit(e(i, :)), ', ') '}'];
    end
    text = sprintf('static const hyst_everett_t %s = {\n    %du, %s,\n    {%s}};\n', name, ...
                   p.degree, strjoin(lit([p.lo p.hi p.y_lo]), ', '), ...
                   strjoin(rows, sprintf(',\n     ')));
  else
    text = sprintf('static const hyst_poly_t %s = {\n    %du, %s,\n    {%s}};\n', name, ...
                   numel(p.coeffs) - 1, strjoin(lit([p.lo p.hi]), ', '), ...
                   strjoin(lit(p.coeffs), sprintf(',\n     ')));
  end
end

function text = creep_text(p, name)
% The creep term's block, as the host tool writes it after the declaration
% (header_creep() in tools/cli/model_file.c); '' without a creep term.
  text = '';
  if isempty(p.creep_tau)
    return;
  end
  lit = @(v) strjoin(strcat('HYST_REAL_C(', c_numbers(v, 17), ')'), ', ');
  text = sprintf(['\n/* creep: add hyst_creep_step() of the model''s input to its output\n' ...
                  ' * (hyst/creep.h): hyst_creep_init(&creep, %s_CREEP_TERMS,\n' ...
                  ' * %s_creep_tau, %s_creep_weight, lo) */\n#define %s_CREEP_TERMS %du\n' ...
                  'static const hyst_wide_t %s_creep_tau[%s_CREEP_TERMS] = {%s};\n' ...
                  'static const hyst_wide_t %s_creep_weight[%s_CREEP_TERMS] = {%s};\n'], ...
                 name, name, name, name, numel(p.creep_tau), name, name, lit(p.creep_tau), ...
                 name, name, lit(p.creep_weight));
end

function text = compensator_text(p, name, intervals, rows)
% The compensator's table built by the library (hyst_mex inv_table or
% inv_table_everett) in float and in double, sealed, as hyst header
% --compensator writes it.
  everett = strcmp(p.kind, 'everett');
  classes = {'single', 'double'};
  built = cell(2, 4);                 % per class: table, crc, max_err, exact
  for k = 1:2
    if everett
      [built{k, :}] = hyst_mex('inv_table_everett', p.degree, p.lo, p.hi, p.y_lo, p.terms, ...
                               intervals, rows, classes{k});
    else
      [built{k, :}] = hyst_mex('inv_table', p.coeffs, p.lo, p.hi, intervals, classes{k});
    end
  end
  if everett
    what = {'', ' per row'};
    len = sprintf('HYST_EVERETT_INV_TABLE_LEN(%s_ROWS, %s_INTERVALS)', name, name);
    use = sprintf([' *   hyst_curve_from_everett(&fwd, &%s);\n' ...
                   ' *   hyst_curve_everett_inverse_table_const(&comp, &fwd, %s_table, ' ...
                   '%s_ROWS,\n *                                          %s_INTERVALS, ' ...
                   '&%s_seal);\n *   hyst_init_curve(&S, &comp, ...);  // comp outlives S */\n' ...
                   '#define %s_ROWS %du\n'], name, name, name, name, name, name, rows);
  else
    what = {'f0^-1 in ', ''};
    len = sprintf('HYST_INV_TABLE_LEN(%s_INTERVALS)', name);
    use = sprintf([' *   hyst_curve_from_poly(&fwd, &%s);\n' ...
                   ' *   hyst_curve_inverse_table_const(&comp, &fwd, %s_table, %s_INTERVALS,\n' ...
                   ' *                                  &%s_seal);\n' ...
                   ' *   hyst_init_curve(&S, &comp, ...);  // comp outlives S */\n'], ...
                  name, name, name, name);
  end
  about = ['\n/* The compensator''s table, built by ''hyst header --compensator'' in float and in\n' ...
           ' * double and sealed: %s%d intervals%s, %d of them solved per sample instead;\n' ...
           ' * worst error measured by the build %.3g (float) / %.3g (double) of the drive\n' ...
           ' * range. Firmware takes it from flash instead of building it at init (checks:\n' ...
           ' * the seal, then a few knots against the model):\n'];
  text = [sprintf(about, what{1}, intervals, what{2}, built{1, 4}, built{1, 3}, built{2, 3}), ...
          use, sprintf('#define %s_INTERVALS %du\n#ifdef HYST_USE_DOUBLE\n', name, intervals), ...
          table_text(name, len, built(2, :)), sprintf('#else\n'), ...
          table_text(name, len, built(1, :)), sprintf('#endif\n')];
end

function text = table_text(name, len, built)
% One variant's table, an interval (four numbers) per line, and its seal.
% BUILT: the table (its class the variant's), the seal's crc and max_err.
  [table, crc, max_err] = built{1:3};
  if isa(table, 'single')
    type = 'float';
    numbers = strcat(c_numbers(double(table), 9), 'f');
  else
    type = 'double';
    numbers = c_numbers(table, 17);
  end
  n = numel(numbers);
  before = repmat({' '}, 1, n);
  before(1:4:n) = {sprintf('\n    ')};
  after = repmat({','}, 1, n);
  after{n} = '';
  parts = [before; numbers(:)'; after];
  seal = c_numbers(max_err, 17);
  text = [sprintf('static const %s %s_table[%s] = {', type, name, len), parts{:}, ...
          sprintf('};\nstatic const hyst_table_seal_t %s_seal = {0x%sul, %s};\n', name, ...
                  dec2hex(crc, 8), seal{1})];
end

function t = c_numbers(v, digits)
% The numbers V as C floating literals of DIGITS significant digits, each
% with a '.' or an exponent (the host tool's cli_c_number()): a cell row.
  t = strsplit(sprintf(sprintf('%%.%dg\n', digits), v), sprintf('\n'));
  t = regexprep(t(1:end - 1), '^(-?[0-9]+)$', '$1.0');
end

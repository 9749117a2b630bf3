% SPDX-License-Identifier: MIT
function failed = run_tests(root, ref, cli)
% RUN_TESTS  Tests of the MATLAB/Octave wrappers (tools/test_octave runs them).
%   FAILED = RUN_TESTS(ROOT, REF, CLI): ROOT the repository, REF the C
%   program hyst_ref (python/tests/ref: the library's block calls on raw
%   arrays), CLI the host tool hyst. Prints one line per test and the summary
%   'octave: N passed, M failed'; returns M.
  addpath(fullfile(root, 'matlab'));
  ctx = struct('root', root, 'ref', ref, 'cli', cli, 'tmp', tempname());
  mkdir(ctx.tmp);
  tests = {@t_sim_f64_bitexact, @t_sim_f32_bitexact, @t_inv_bitexact, @t_inv_table_bitexact, ...
           @t_bounded_memory_bitexact, @t_inv_undoes_sim, @t_fit_measured, ...
           @t_fit_equals_cli, @t_errors_status_names, @t_usage_errors, ...
           @t_save_load_roundtrip, @t_load_rejects, @t_readme_block, ...
           @t_everett_reference, @t_everett_errors, @t_everett_fit, @t_everett_fit_growing, ...
           @t_everett_save_load, @t_everett_load_rejects, @t_everett_inv, ...
           @t_everett_inv_table_bitexact, @t_everett_inv_table_error, ...
           @t_everett_inv_table_monotone, @t_everett_inv_table_arguments, ...
           @t_header_equals_cli, @t_header_tables, @t_header_file, @t_header_arguments, ...
           @t_creep_sim_inv_equal_cli, @t_creep_sum_of_lags, @t_creep_save_load, ...
           @t_creep_load_rejects, @t_creep_header_equals_cli, @t_creep_fit, @t_creep_errors, ...
           @t_readers_agree, @t_fit_delay_saved, @t_fit_chooses_as_cli, ...
           @t_fit_searches_delays_as_cli, @t_fit_validated_as_cli, @t_rate_sim_inv_equal_cli, @t_rate_written_as_cli, ...
           @t_rate_refused, @t_rate_fit_as_cli, @t_grid_sim_inv_equal_cli, @t_grid_written_as_cli, ...
           @t_grid_header_equals_cli, @t_grid_refused, @t_grid_fit_as_cli, ...
           @t_grid_chosen_as_cli, @t_grid_fit_undetermined, @t_spline_runs_as_its_polynomial, ...
           @t_spline_inv_undoes_sim, @t_spline_inv_table_equals_cli, @t_spline_save_load, @t_spline_header_equals_cli, ...
           @t_spline_refused, @t_spline_fit_recovers_the_plant, @t_fit_missing_first_input, ...
           @t_fit_refuses_record, @t_save_writes_regular_files_only, ...
           @t_header_refuses_what_init_refuses, @t_fit_checks_record_as_cli, ...
           @t_fit_recovers_a_simulated_plant, @t_fit_warns_degree_on_minor_loops, ...
           @t_fit_writes_e_of_the_width_as_f0, @t_fit_widens_symmetric_kinds_as_cli};
  passed = 0;
  failed = 0;
  for k = 1:numel(tests)
    name = func2str(tests{k});
    try
      tests{k}(ctx);
      passed = passed + 1;
      printf('PASS %s\n', name);
    catch err
      failed = failed + 1;
      printf('FAIL %s: %s\n', name, err.message);
    end
  end
  confirm_recursive_rmdir(false, 'local');
  rmdir(ctx.tmp, 's');
  printf('octave: %d passed, %d failed\n', passed, failed);
end

% ---- helpers ----

function check(cond, varargin)
  if ~cond
    error('check:failed', varargin{:});
  end
end

function f0 = paper_f0()
  % the paper's Eq. 20 on [0, 40] V, highest power first
  f0 = struct('coeffs', [-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1], 'lo', 0, 'hi', 40);
end

function x = signal(n, lo, hi, seed)
  % nested minor loops (a damped oscillation), then sweeps between random
  % ends, repeated samples, a few samples outside [lo, hi]; deterministic
  rand('state', seed);
  t = (0:n - 1)';
  mid = (lo + hi) / 2;
  a = mid + (hi - lo) / 2 * exp(-t / (n / 6)) .* cos(t * 0.37);
  ends = lo + (hi - lo) * rand(ceil(n / 40), 1);
  b = interp1(1:numel(ends), ends, linspace(1, numel(ends), n)');
  x = [a; b];
  x(5:97:end) = x(4:97:end - 1);      % repeated samples
  x(250) = hi + 1;                    % clamped
  x(600) = lo - 1;
end

function [y, status, inv_err] = run_ref(ctx, kind, cls, model, x, varargin)
  % hyst_ref over x (raw numbers of class cls); extra key=value arguments.
  % A model of kind everett goes as its E (degree=, y_lo=, terms=). inv_err:
  % hyst_curve_inverse_error() of the compensator (hyst_ref's err=)
  fin = fullfile(ctx.tmp, 'in.raw');
  fout = fullfile(ctx.tmp, 'out.raw');
  ferr = fullfile(ctx.tmp, 'err.txt');
  fid = fopen(fin, 'w');
  fwrite(fid, x, cls);
  fclose(fid);
  type = 'f64';
  if strcmp(cls, 'single')
    type = 'f32';
  end
  list = @(v) strjoin(arrayfun(@(c) sprintf('%.17g', c), v, 'UniformOutput', false), ',');
  if isfield(model, 'kind') && strcmp(model.kind, 'everett')
    what = sprintf('degree=%d y_lo=%.17g terms=%s', model.degree, model.y_lo, list(model.terms));
  else
    what = ['coeffs=' list(model.coeffs)];
  end
  if exist(ferr, 'file')
    delete(ferr);
  end
  cmd = sprintf('"%s" %s type=%s lo=%.17g hi=%.17g %s in="%s" out="%s" err="%s" %s', ctx.ref, ...
                kind, type, model.lo, model.hi, what, fin, fout, ferr, strjoin(varargin, ' '));
  [rc, out] = system(cmd);
  check(rc == 0, 'hyst_ref failed: %s', out);
  status = str2double(out);
  fid = fopen(fout, 'r');
  y = fread(fid, Inf, ['*' cls]);
  fclose(fid);
  y = reshape(y, size(x));
  inv_err = NaN;                      % hyst_ref writes it for a compensator it initialised
  if nargout > 2 && exist(ferr, 'file')
    inv_err = str2double(fileread(ferr));
  end
end

function out = run_cli(ctx, args)
  [rc, out] = system(sprintf('"%s" %s', ctx.cli, args));
  check(rc == 0, 'hyst %s failed: %s', args, out);
end

function expect_error(id, fn)
  % fn() must raise an error with identifier id; returns its message
  try
    fn();
  catch err
    check(strcmp(err.identifier, id), 'identifier %s, expected %s (%s)', err.identifier, id, ...
          err.message);
    return;
  end
  error('check:failed', 'no error, expected %s', id);
end

function msg = error_message(fn)
  msg = '';
  try
    fn();
  catch err
    msg = err.message;
  end
end

% ---- tests ----

function t_sim_f64_bitexact(ctx)
  % double: hyst_f64_process, bit for bit and the same status as the C program
  m = paper_f0();
  x = signal(4000, m.lo, m.hi, 1);
  [y, st] = hyst_sim(m, x);
  [yc, stc] = run_ref(ctx, 'sim', 'double', m, x);
  check(strcmp(class(y), 'double') && isequal(size(y), size(x)), 'class or shape');
  check(isequal(typecast(y, 'uint64'), typecast(yc, 'uint64')), 'outputs differ from hyst_ref');
  check(st == stc && st == 1, 'status %d, hyst_ref %d (1 expected: clamped samples)', st, stc);
  % a row in gives a row out, the same numbers
  check(isequal(hyst_sim(m, x'), y'), 'a row vector');
end

function t_sim_f32_bitexact(ctx)
  % single: hyst_f32_process (what a Cortex-M4F computes), bit for bit
  m = paper_f0();
  x = single(signal(4000, m.lo, m.hi, 2));
  x(1234) = NaN;                      % ignored, as in firmware
  [y, st] = hyst_sim(m, x);
  [yc, stc] = run_ref(ctx, 'sim', 'single', m, x);
  check(strcmp(class(y), 'single'), 'class %s', class(y));
  check(isequal(typecast(y, 'uint32'), typecast(yc, 'uint32')), 'outputs differ from hyst_ref');
  check(st == stc, 'status %d, hyst_ref %d', st, stc);
  check(y(1234) == y(1233), 'a NaN sample returns the previous output');
  % float and double differ (otherwise the test above proves nothing about f32)
  check(any(double(y) ~= hyst_sim(m, double(x))), 'single equals double everywhere');
end

function t_inv_bitexact(ctx)
  % the compensator: hyst_*_init_inverse_exact, bit for bit
  m = paper_f0();
  lo = polyval(m.coeffs, m.lo);
  hi = polyval(m.coeffs, m.hi);
  yd = signal(3000, lo, hi, 3);
  [x, st] = hyst_inv(m, yd);
  [xc, stc] = run_ref(ctx, 'inv', 'double', m, yd);
  check(isequal(typecast(x, 'uint64'), typecast(xc, 'uint64')) && st == stc, 'f64 differs');
  [x, st] = hyst_inv(m, single(yd));
  [xc, stc] = run_ref(ctx, 'inv', 'single', m, single(yd));
  check(isequal(typecast(x, 'uint32'), typecast(xc, 'uint32')) && st == stc, 'f32 differs');
end

function t_inv_table_bitexact(ctx)
  % the firmware's compensator (hyst_*_init_inverse_table), bit for bit, its
  % measured error within the 1e-5 target (the asymmetric kind's table:
  % t_everett_inv_table_*)
  m = paper_f0();
  yd = signal(3000, polyval(m.coeffs, m.lo), polyval(m.coeffs, m.hi), 4);
  [x, st, ~, err] = hyst_inv(m, yd, 'intervals', 256);
  [xc, stc] = run_ref(ctx, 'inv', 'double', m, yd, 'intervals=256');
  check(isequal(typecast(x, 'uint64'), typecast(xc, 'uint64')) && st == stc, 'f64 differs');
  check(err > 0 && err <= 1e-5, 'measured error %g', err);
  [xe, ~, ~, err0] = hyst_inv(m, yd);
  check(err0 == 0 && max(abs(x - xe)) > 0, 'the exact compensator is the default');
  [x, st] = hyst_inv(m, single(yd), 'intervals', 32);
  [xc, stc] = run_ref(ctx, 'inv', 'single', m, single(yd), 'intervals=32');
  check(isequal(typecast(x, 'uint32'), typecast(xc, 'uint32')) && st == stc, 'f32 differs');
  expect_error('hyst:usage', @() hyst_inv(m, yd, 'intervals', 0.5));
  expect_error('hyst:usage', @() hyst_sim(m, yd, 'intervals', 16));
end

function t_bounded_memory_bitexact(ctx)
  % few turning points (loops merge: status 2) and a deadband, as the C program
  m = paper_f0();
  x = signal(3000, m.lo, m.hi, 4);
  [y, st, ntp] = hyst_sim(m, x, 'capacity', 4, 'deadband', 0.05);
  [yc, stc] = run_ref(ctx, 'sim', 'double', m, x, 'cap=4', 'deadband=0.05');
  check(isequal(typecast(y, 'uint64'), typecast(yc, 'uint64')), 'outputs differ');
  check(st == stc && st > 0, 'status %d, hyst_ref %d', st, stc);
  check(ntp <= 8, '%d turning points with capacity 4', ntp);
  check(any(y ~= hyst_sim(m, x)), 'bounded memory changed nothing');
end

function t_inv_undoes_sim(~)
  % hyst_sim(hyst_inv(y)) = y and hyst_inv(hyst_sim(x)) = x, within rounding
  m = paper_f0();
  x = signal(5000, m.lo, m.hi, 5);
  x = min(max(x, m.lo), m.hi);
  y = hyst_sim(m, x);
  err = max(abs(hyst_inv(m, y) - x));
  check(err <= 1e-9 * (m.hi - m.lo), 'double: |inv(sim(x)) - x| up to %g', err);
  xs = single(x);
  err = max(abs(double(hyst_inv(m, hyst_sim(m, xs))) - x));
  check(err <= 1e-3 * (m.hi - m.lo), 'single: |inv(sim(x)) - x| up to %g', err);
  span = polyval(m.coeffs, m.hi) - polyval(m.coeffs, m.lo);
  err = max(abs(hyst_sim(m, hyst_inv(m, y)) - y));
  check(err <= 1e-9 * span, 'double: |sim(inv(y)) - y| up to %g', err);
end

function t_fit_measured(ctx)
  % the measured piezo record: an increasing f0 that predicts the second
  % half from the first within 3 % of the output range, better than a line
  d = load(fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat'));
  x = d(:, 1);
  y = d(:, 5);
  half = floor(numel(x) / 2);
  f = hyst_fit(x(1:half), y(1:half), 'degree', 3, 'skip', 350, 'delay', 1);
  check(f.increasing && numel(f.coeffs) == 4 && f.degree == 3, 'not an increasing cubic');
  check(f.used > 0.9 * (half - 351) && f.rising > 0 && f.falling > 0, 'used %d', f.used);
  range = max(y) - min(y);
  check(f.rms > 0 && f.rms < 0.03 * range, 'rms %g of range %g', f.rms, range);
  model = struct('coeffs', f.coeffs, 'lo', min(x), 'hi', max(x));
  p = hyst_sim(model, x);             % from A0: compare after the settling
  e3 = max(abs(p(half + 1:end - 1) - y(half + 2:end)));
  g = hyst_fit(x(1:half), y(1:half), 'degree', 1, 'skip', 350, 'delay', 1);
  p1 = hyst_sim(struct('coeffs', g.coeffs, 'lo', min(x), 'hi', max(x)), x);
  e1 = max(abs(p1(half + 1:end - 1) - y(half + 2:end)));
  check(e3 < 0.03 * range, 'prediction error %g of range %g', e3, range);
  check(e3 < e1 / 2, 'cubic %g is not far better than a line %g', e3, e1);
  r = hyst_fit(x, y, 'degree', 3, 'method', 'reflect', 'skip', 350, 'delay', 1, 'domain', [min(x) max(x)]);
  check(strcmp(r.method, 'reflect') && r.increasing, 'reflect estimator');
end

function t_fit_equals_cli(ctx)
  % hyst fit prints the same coefficients (15 digits) and domain
  data = fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat');
  f = hyst_fit(load(data)(:, 1), load(data)(:, 5), 'degree', 4, 'skip', 350, 'delay', 1);
  out = strsplit(run_cli(ctx, ['fit --degree 4 --skip 350 --delay 1 --xcol 1 --ycol 5 "' data '"']), "\n");
  c = str2double(strsplit(out{1}, ','));
  dom = str2double(strsplit(out{2}, ','));
  check(numel(c) == 5 && all(abs(c - f.coeffs) <= 1e-14 * abs(f.coeffs) + 1e-300), ...
        'coefficients %s vs %s', out{1}, mat2str(f.coeffs, 15));
  check(all(abs(dom - [f.lo f.hi]) <= 1e-14 * abs([f.lo f.hi])), 'domain %s', out{2});
end

function t_errors_status_names(~)
  % a library error raises hyst:<name> with hyst_status_str() in the message
  cases = {
    -6, 'ERR_NOT_INCREASING', @() hyst_sim(struct('coeffs', [-1 0], 'lo', 0, 'hi', 1), 0)
    -2, 'ERR_DOMAIN', @() hyst_inv(struct('coeffs', [1 0], 'lo', 1, 'hi', 1), 0)
    -4, 'ERR_CAPACITY', @() hyst_sim(paper_f0(), 0, 'capacity', 1)
    -21, 'ERR_ILL_CONDITIONED', @() hyst_sim(struct('coeffs', [1 0 0 0 0 0 0 0 0 0], 'lo', -1, 'hi', 1), single(0))
    -10, 'ERR_SINGULAR', @() hyst_fit([0 1 0 1 0 1], [0 1 0 1 0 1], 'degree', 3, 'delay', 0)
    -3, 'ERR_DEGREE', @() hyst_fit(0:9, 0:9, 'degree', 0, 'delay', 0)
  };
  for k = 1:size(cases, 1)
    [text, name] = hyst_mex('status_str', cases{k, 1});
    check(strcmp(name, cases{k, 2}), 'status %d is %s', cases{k, 1}, name);
    expect_error(['hyst:' name], cases{k, 3});
    msg = error_message(cases{k, 3});
    check(~isempty(strfind(msg, text)) && ~isempty(strfind(msg, name)), ...
          '%s: message ''%s'' lacks ''%s''', name, msg, text);
  end
  % x^9 on [-1, 1] is refused in float32 only: double runs it
  hyst_sim(struct('coeffs', [1 0 0 0 0 0 0 0 0 0], 'lo', -1, 'hi', 1), 0);
  % a warning is not an error: clamped samples return status 1
  [~, st] = hyst_sim(paper_f0(), [0 50 20]);
  check(st == 1, 'status %d for a clamped sample', st);
end

function [x, y] = loops_record()
  % a minor loop whose response E of degree 2 fits exactly (y = x + x^2 / 10)
  x = [linspace(0, 10, 200) linspace(10, 2, 150) linspace(2, 8, 100) linspace(8, 0, 150)]';
  y = x + 0.1 * x .^ 2;
end

function t_fit_missing_first_input(~)
  % a NaN input is a missing sample, also the first: the fit is that of the
  % record without it (the inputs' range is the others', not NaN)
  [x, y] = loops_record();
  x(1) = NaN;
  f = hyst_fit(x, y);
  r = hyst_fit(x(2:end), y(2:end));
  check(strcmp(f.kind, r.kind) && f.degree == r.degree && f.lo == r.lo && f.hi == r.hi && ...
        f.lo == 0 && max(abs(f.terms(:) - r.terms(:))) <= 1e-12 * max(abs(r.terms(:))), ...
        'fit %s degree %d on [%g, %g], without the sample %s degree %d on [%g, %g]', f.kind, ...
        f.degree, f.lo, f.hi, r.kind, r.degree, r.lo, r.hi);
  e = hyst_fit(x, y, 'kind', 'everett', 'degree', 2);
  check(max(abs(e.terms(:)' - [10 20 10])) < 1e-8, 'terms of E %s', mat2str(e.terms));
end

function t_fit_refuses_record(~)
  % what hyst fit refuses in a file is refused here too, named
  [x, y] = loops_record();
  bad = x;
  bad(6) = Inf;
  cases = {{bad, y}, 'x\(6\) is Inf'; {x, -1 ./ (y - y(1))}, 'y\(1\) is -Inf'; ...
           {x, y, 'delay', -1}, 'delay must be a whole'; {x, y, 'delay', 1.5}, 'delay must be'; ...
           {x, y, 'skip', 2.5}, 'skip must be a whole'; {x, y, 'skip', 600}, 'leave no sample'; ...
           {ones(50, 1), (1:50)'}, 'x is constant'; {x, NaN(size(y))}, 'y is constant'; ...
           {x, -y}, 'y falls as x rises'};
  for i = 1:size(cases, 1)
    msg = '';
    try
      hyst_fit(cases{i, 1}{:});
    catch err
      check(strcmp(err.identifier, 'hyst:usage') == isempty(strfind(cases{i, 2}, 'leave')), ...
            'case %d: identifier %s', i, err.identifier);
      msg = err.message;
    end
    check(~isempty(regexp(msg, cases{i, 2}, 'once')), 'case %d: message "%s"', i, msg);
  end
end

function t_usage_errors(~)
  m = paper_f0();
  expect_error('hyst:usage', @() hyst_sim(m, int16([1 2])));
  expect_error('hyst:usage', @() hyst_sim(m, [1 2], 'capcity', 4));
  expect_error('hyst:usage', @() hyst_sim(struct('coeffs', [1 0]), 0));
  expect_error('hyst:usage', @() hyst_sim(struct('coeffs', 1:11, 'lo', 0, 'hi', 1), 0));
  expect_error('hyst:usage', @() hyst_fit(1:3, 1:4));
  expect_error('hyst:usage', @() hyst_fit(1:3, 1:3, 'method', 'other'));
  expect_error('hyst:usage', @() hyst_mex('nosuchcommand'));
  check(strcmp(hyst_mex('version'), regexprep(hyst_mex('version'), '[^0-9.]', '')) && ...
        numel(strsplit(hyst_mex('version'), '.')) == 3, 'version %s', hyst_mex('version'));
end

function t_save_writes_regular_files_only(ctx)
  % as hyst fit --save: a link is written through, kept; a directory, a pipe
  % or a link to nothing is refused, left as it was
  d = fullfile(ctx.tmp, 'regular');
  mkdir(d);
  f = struct('coeffs', [1 0], 'lo', 0, 'hi', 1);
  real = fullfile(d, 'real.hyst');
  fid = fopen(real, 'w');
  fputs(fid, 'old');
  fclose(fid);
  link = fullfile(d, 'link.hyst');
  symlink(real, link);
  hyst_model_save(link, f);
  [st, err] = lstat(link);
  g = hyst_model_load(real);
  check(err == 0 && S_ISLNK(st.mode) && isequal(g.coeffs(:)', [1 0]), 'the link written through');
  pipe = fullfile(d, 'pipe');
  check(mkfifo(pipe, 600) == 0, 'mkfifo');  % Octave reads the mode's digits as octal
  dangling = fullfile(d, 'dangling.hyst');
  symlink(fullfile(d, 'nowhere', 'm.hyst'), dangling);
  cases = {d, 'is a directory'; pipe, 'not a regular file'; dangling, 'link to nothing'};
  for i = 1:size(cases, 1)
    before = sort({dir(d).name});
    msg = error_message(@() hyst_model_save(cases{i, 1}, f));
    check(~isempty(strfind(msg, cases{i, 2})), 'case %d: message "%s"', i, msg);
    check(isequal(sort({dir(d).name}), before), 'case %d: a file left beside', i);
  end
  [st, err] = lstat(pipe);
  check(err == 0 && S_ISFIFO(st.mode), 'the pipe replaced');
end

function t_header_refuses_what_init_refuses(~)
  % as hyst header: no header of a model whose init would fail
  expect_error('hyst:ERR_NOT_INCREASING', ...
               @() hyst_header(struct('coeffs', [-1 0], 'lo', 0, 'hi', 1), 'falls'));
  e = struct('kind', 'everett', 'degree', 1, 'lo', 0, 'hi', 1, 'y_lo', 0, 'terms', -1);
  expect_error('hyst:ERR_NOT_MONOTONE', @() hyst_header(e, 'e'));
  t = hyst_header(struct('coeffs', [1 0], 'lo', 0, 'hi', 1), 'rises');
  check(~isempty(strfind(t, 'hyst_poly_t rises')), 'header %s', t);
end

function t_save_load_roundtrip(ctx)
  d = load(fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat'));
  f = hyst_fit(d(:, 1), d(:, 5), 'degree', 5, 'skip', 350, 'delay', 1);
  file = fullfile(ctx.tmp, 'model.txt');
  hyst_model_save(file, f);
  m = hyst_model_load(file);
  check(isequal(m.coeffs, f.coeffs) && m.lo == f.lo && m.hi == f.hi, 'not the same doubles');
  % the record drifts: hyst_fit (creep 'auto', as hyst fit) fitted a creep term too
  % the delay hyst_fit fitted at is the model's: saved and read back
  check(isequal(fieldnames(m), {'coeffs'; 'lo'; 'hi'; 'delay'; 'creep_tau'; 'creep_weight'}) && ...
        m.delay == 1, 'fields');
  check(isequal([m.creep_tau m.creep_weight], [f.creep_tau f.creep_weight]), 'the creep term');
  g = hyst_fit(d(:, 1), d(:, 5), 'degree', 5, 'skip', 350, 'delay', 1, 'creep', 'none');
  hyst_model_save(file, g);
  check(isequal(fieldnames(hyst_model_load(file)), {'coeffs'; 'lo'; 'hi'; 'delay'}), ...
        'fields without a creep term');
  hyst_model_save(file, f);
  % the host tool's model file (hyst fit --save), delay included
  cli_file = fullfile(ctx.tmp, 'cli.hyst');
  run_cli(ctx, ['fit --degree 4 --skip 350 --delay 2 --xcol 1 --ycol 5 --save "' cli_file '" "' ...
                fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat') '"']);
  c = hyst_model_load(cli_file);
  check(c.delay == 2 && numel(c.coeffs) == 5, 'hyst fit --save read back: delay %g', c.delay);
  c.delay = 3;
  hyst_model_save(file, c);
  check(hyst_model_load(file).delay == 3, 'delay written and read');
  check(isequal(hyst_sim(m, d(:, 1)), hyst_sim(f, d(:, 1))), 'simulations differ');
  text = fileread(file);
  check(strncmp(text, sprintf('hyst-model-text 1\n'), 18), 'first line: %s', text);
  % written whole or not at all: a failed save leaves the old file and no other
  before = dir(ctx.tmp);
  missing = fullfile(ctx.tmp, 'no_such_dir', 'model.txt');
  expect_error('hyst:model_file', @() hyst_model_save(missing, f));
  check(~exist(fileparts(missing), 'dir'), 'the directory was made');
  folder = fullfile(ctx.tmp, 'a_dir.txt');
  mkdir(folder);
  expect_error('hyst:model_file', @() hyst_model_save(folder, f));
  check(exist(folder, 'dir') == 7, 'the directory is gone');
  rmdir(folder);
  check(isequal(sort({dir(ctx.tmp).name}), sort({before.name})), 'a file was left behind');
  check(strcmp(fileread(file), text), 'the saved file changed');
end

function t_load_rejects(ctx)
  file = fullfile(ctx.tmp, 'bad.txt');
  good = {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi 40', 'coeffs 1 2'};
  bad = {
    {'hyst-model-text 2', 'kind poly', 'lo 0', 'hi 40', 'coeffs 1 2'}, 'hyst-model-text 1'
    {'kind poly', 'lo 0', 'hi 40', 'coeffs 1 2'}, ':1:'
    [good {'gain 3'}], ':6: field 1: ''gain'' is not a key'
    [good {'lo 1'}], ':6: field 1: ''lo'' given twice'
    good([1 2 3 5]), 'the key hi is missing'
    {'hyst-model-text 1', 'kind pwl', 'lo 0', 'hi 40', 'coeffs 1 2'}, ':2: field 2: kind must be ''poly'', ''everett'', ''everett_grid'' or ''spline'''
    {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi Inf', 'coeffs 1 2'}, ':4: field 2: ''Inf'' is not a finite number'
    {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi 40', 'coeffs 1 x'}, ':5: field 3: ''x'' is not a finite number'
    [good {'delay -2.5'}], ':6: field 2: ''-2.5'' is not a delay of 0 to 1000000000 samples'
    [good {'identified 10 50'}], ':6: field 3: identified 10 50 is not a range within [lo, hi]'
    {'hyst-model-text 1', 'kind poly', 'lo 1,5', 'hi 40', 'coeffs 1 2'}, ':3: field 2: ''1,5'' is not a finite number (the decimal mark is ''.'')'
  };
  write_lines(file, [good {'', '# a comment'}]);
  m = hyst_model_load(file);
  check(isequal(m.coeffs, [1 2]) && m.lo == 0 && m.hi == 40, 'the good file');
  % a sub-sample delay and the identified range, read and written back
  write_lines(file, [good {'delay 2.5', 'identified 5 30'}]);
  m = hyst_model_load(file);
  check(m.delay == 2.5 && isequal(m.identified, [5 30]), 'delay 2.5, identified 5 30 read');
  hyst_model_save(file, m);
  back = hyst_model_load(file);
  check(back.delay == 2.5 && isequal(back.identified, [5 30]), 'delay and identified written back');
  expect_load_errors(file, bad);
  expect_error('hyst:model_file', @() hyst_model_load(fullfile(ctx.tmp, 'nosuchfile')));
end

function expect_load_errors(file, bad)
  % each row of bad: the lines of a file, and what hyst_model_load's
  % hyst:model_file message must hold
  for k = 1:size(bad, 1)
    write_lines(file, bad{k, 1});
    msg = error_message(@() hyst_model_load(file));
    expect_error('hyst:model_file', @() hyst_model_load(file));
    check(~isempty(strfind(msg, bad{k, 2})), 'case %d: message ''%s''', k, msg);
  end
end

function write_lines(file, lines)
  fid = fopen(file, 'w');
  fprintf(fid, '%s\n', lines{:});
  fclose(fid);
end

function t_readme_block(ctx)
  % the README's MATLAB/Octave quick start runs as written from the root
  text = fileread(fullfile(ctx.root, 'README.md'));
  parts = strsplit(text, sprintf('\n## MATLAB / Octave\n'));
  check(numel(parts) == 2, 'README: one section ''## MATLAB / Octave''');
  section = strsplit(parts{2}, sprintf('\n## ')){1};
  blocks = regexp(section, '```matlab\n(.*?)```', 'tokens');
  check(numel(blocks) == 1, 'README: one ```matlab block in that section');
  here = pwd();
  cd(ctx.root);
  try
    out = evalc(blocks{1}{1});
  catch err
    cd(here);
    rethrow(err);
  end
  cd(here);
  check(~isempty(strtrim(out)), 'the quick start prints nothing');
end

% ---- the asymmetric kind (kind everett) ----

function e = e3()
  % an asymmetric E of degree 3 on [0, 10]: terms of w, w t, w t^2, w^2, w^2 t, w^3
  e = struct('kind', 'everett', 'degree', 3, 'lo', 0, 'hi', 10, 'y_lo', -1, ...
             'terms', [8 3 -1 2 1 -0.5]);
end

function es = everett_examples()
  % E of degrees 3, 2 and 4 that init accepts
  es = {e3(), ...
        struct('kind', 'everett', 'degree', 2, 'lo', 0, 'hi', 3.6, 'y_lo', -0.035, ...
               'terms', [0.61 0.02 -0.1]), ...
        struct('kind', 'everett', 'degree', 4, 'lo', -5, 'hi', 15, 'y_lo', 2, ...
               'terms', [4 1 0.5 -0.2 1 0.3 -0.1 0.5 0.1 -0.3])};
end

function v = e_value(e, a, b)
  % E(a, b) term by term: w^i t^j, i = 1..degree, j = 0..degree - i
  span = e.hi - e.lo;
  w = (a - b) / span;
  t = (b - e.lo) / span;
  v = 0;
  k = 1;
  for i = 1:e.degree
    for j = 0:e.degree - i
      v = v + e.terms(k) * w^i * t^j;
      k = k + 1;
    end
  end
end

function out = everett_reference(e, xs)
  % Madelung's rules on a list of turning points (LTPs at odd places, A0
  % first): rising from (b, y_b) y = y_b + E(x, b), falling from (a, y_a)
  % y = y_a - E(a, x); passing the TP before the current one wipes out both;
  % at lo every loop is closed. Inputs clamped, NaN ignored.
  tx = e.lo;
  ty = e.y_lo;
  x_prev = e.lo;
  y = e.y_lo;
  out = zeros(size(xs));
  for k = 1:numel(xs)
    x = xs(k);
    if ~isfinite(x)
      out(k) = y;
      continue;
    end
    x = min(max(x, e.lo), e.hi);
    rising = mod(numel(tx) - 1, 2) == 0;
    if x > x_prev
      if ~rising
        tx(end + 1) = x_prev;
        ty(end + 1) = y;
      end
      while numel(tx) >= 3 && x >= tx(end - 1)
        tx(end - 1:end) = [];
        ty(end - 1:end) = [];
      end
      y = ty(end) + e_value(e, x, tx(end));
    elseif x < x_prev
      if rising
        tx(end + 1) = x_prev;
        ty(end + 1) = y;
      end
      while numel(tx) >= 3 && x <= tx(end - 1)
        tx(end - 1:end) = [];
        ty(end - 1:end) = [];
      end
      y = ty(end) - e_value(e, tx(end), x);
      if x <= e.lo
        tx = e.lo;
        ty = e.y_lo;
        y = e.y_lo;
      end
    end
    x_prev = x;
    out(k) = y;
  end
end

function t_everett_reference(~)
  % double: the plain reference to 1e-9 of the range; single follows it
  e = e3();
  range = e_value(e, e.hi, e.lo);
  x = signal(4000, e.lo, e.hi, 11);
  x(777) = NaN;
  [y, st] = hyst_sim(e, x);
  want = everett_reference(e, x);
  err = max(abs(y - want));
  check(err <= 1e-9 * range, 'double: %g from the reference', err);
  check(st == -7, 'status %d (-7 expected: a NaN sample)', st);
  [~, st] = hyst_sim(e, x(1:700));
  check(st == 1, 'status %d (1 expected: clamped samples)', st);
  ys = hyst_sim(e, single(x));
  check(strcmp(class(ys), 'single') && any(double(ys) ~= y), 'single');
  err = max(abs(double(ys) - want));
  check(err <= 2e-5 * range, 'single: %g from the reference', err);
  % the t terms matter: E of the width only is another model
  w = e;
  w.terms([2 3 5]) = 0;
  check(max(abs(everett_reference(w, x) - want)) > 1e-3 * range, 'E''s t terms changed nothing');
end

function t_everett_errors(~)
  e = struct('kind', 'everett', 'degree', 2, 'lo', 0, 'hi', 3.6, 'y_lo', 0, 'terms', [0.61 0.02 -1]);
  expect_error('hyst:ERR_NOT_MONOTONE', @() hyst_sim(e, 1));
  msg = error_message(@() hyst_sim(e, single(1)));
  check(~isempty(strfind(msg, 'ERR_NOT_MONOTONE, -22')), 'message ''%s''', msg);
  msg = error_message(@() hyst_inv(e, 0.1));
  check(~isempty(strfind(msg, 'hyst_inv: ')) && ~isempty(strfind(msg, 'ERR_NOT_MONOTONE')), ...
        'message ''%s''', msg);
  e.terms = [0.61 0.02 -0.1];
  bad = e;
  bad.degree = 5;
  bad.terms = ones(1, 15);
  expect_error('hyst:ERR_DEGREE', @() hyst_sim(bad, 1));
  bad = e;
  bad.terms = [1 0];
  expect_error('hyst:usage', @() hyst_sim(bad, 1));
  expect_error('hyst:usage', @() hyst_sim(rmfield(e, 'y_lo'), 1));
  expect_error('hyst:usage', @() hyst_fit(1:3, 1:3, 'kind', 'preisach'));
  expect_error('hyst:ERR_SINGULAR', @() hyst_fit([0 1 0 1 0], [0 1 0 1 0], 'kind', 'everett', ...
                                                  'degree', 3, 'delay', 0));
  expect_error('hyst:ERR_DEGREE', @() hyst_fit(0:9, 0:9, 'kind', 'everett', 'degree', 5));
  expect_error('hyst:ERR_ARG', @() hyst_fit(0:9, 0:9, 'kind', 'everett', 'degree', 3, ...
                                            'delay', 0, 'skip', 10));
end

function t_everett_fit_growing(~)
  % excursions growing from a rest in the middle: the first extreme comes in
  % the last third, so every output is fitted and the plant (run from rest,
  % as the model is) recovered
  e = e3();
  x = 5 * ones(50, 1);
  for c = 1:10
    a = 0.5 * c;
    x = [x; (5:0.05:5 + a - 1e-9)'; (5 + a:-0.05:5 - a + 1e-9)'; (5 - a:0.05:5 - 1e-9)'];
  end
  y = hyst_sim(e, x);
  near_end = x <= min(x) + 0.01 * (max(x) - min(x)) | x >= max(x) - 0.01 * (max(x) - min(x));
  check(find(near_end, 1) > 2 * numel(x) / 3, 'first extreme at %d of %d', find(near_end, 1), numel(x));
  f = hyst_fit(x, y, 'kind', 'everett', 'degree', 3, 'delay', 0, 'domain', [e.lo e.hi]);
  check(f.used == numel(x), 'used %d of %d', f.used, numel(x));
  check(max(abs(f.terms - e.terms)) < 1e-3 * max(abs(e.terms)), 'terms %s', mat2str(f.terms, 5));
end

function t_everett_fit(~)
  % a known E from a noisy record of the asymmetric plant: terms, y_lo, rms
  e = e3();
  x = min(max(signal(6000, e.lo, e.hi, 12), e.lo), e.hi);
  sigma = 1e-3 * e_value(e, e.hi, e.lo);
  randn('state', 12);
  y = hyst_sim(e, x) + sigma * randn(size(x));
  f = hyst_fit(x, [y(1); y(1:end - 1)], 'kind', 'everett', 'degree', 3, 'delay', 1, ...
               'domain', [e.lo e.hi]);
  check(strcmp(f.kind, 'everett') && f.degree == 3 && f.monotone, 'kind, degree, monotone');
  check(max(abs(f.terms - e.terms)) < 0.1, 'terms %s', mat2str(f.terms, 5));
  check(abs(f.y_lo - e.y_lo) < 0.02, 'y_lo %g', f.y_lo);
  check(f.rms > 0.9 * sigma && f.rms < 1.1 * sigma, 'rms %g, noise %g', f.rms, sigma);
  check(f.used == numel(x) - 1, 'used %d', f.used);
  xt = min(max(signal(3000, e.lo, e.hi, 13), e.lo), e.hi);
  err = hyst_sim(f, xt) - hyst_sim(e, xt);
  check(sqrt(mean(err .^ 2)) < sigma, 'prediction RMS %g', sqrt(mean(err .^ 2)));
  % a fit that is not monotone warns and the model is refused: a plant that
  % rises then falls (one that clearly falls is refused before the fit:
  % t_fit_refuses_record)
  t = linspace(0, 1, 400)';
  u = abs(sin(6 * pi * t));
  warning('off', 'hyst:not_monotone');
  g = hyst_fit(u, 4 * u .* (1 - u), 'kind', 'everett', 'degree', 2, 'delay', 0);
  warning('on', 'hyst:not_monotone');
  check(~g.monotone, 'a plant that rises then falls gave a monotone E');
  expect_error('hyst:ERR_NOT_MONOTONE', @() hyst_sim(g, u));
  % major loops alone: E of degree 3 in full is singular, linear in t
  % ('tdegree' 1) it is recovered, the w t^2 term 0
  p = struct('kind', 'everett', 'degree', 3, 'lo', 0, 'hi', 40, 'y_lo', 0.5, ...
             'terms', [3 1 0 2 -0.5 0.4]);
  xm = repmat([0:0.25:40, 39.75:-0.25:0.25]', 4, 1);
  ym = hyst_sim(p, xm);
  expect_error('hyst:ERR_SINGULAR', @() hyst_fit(xm, ym, 'kind', 'everett', 'degree', 3, ...
                                                  'delay', 0));
  h = hyst_fit(xm, ym, 'kind', 'everett', 'degree', 3, 'tdegree', 1, 'delay', 0);
  check(h.t_degree == 1 && h.monotone && h.terms(3) == 0, 't-degree 1: %s', mat2str(h.terms));
  check(max(abs(h.terms - p.terms)) < 1e-9, 't-degree 1 terms %s', mat2str(h.terms, 12));
  expect_error('hyst:usage', @() hyst_fit(xm, ym, 'tdegree', 1));
  % the same record from inside a loop (falling from 40 at 30.25): the
  % outputs before the input first comes near an end are not fitted
  xi = xm(200:end);
  head = find(xi <= 0.4 | xi >= 39.6, 1) - 1;
  k = hyst_fit(xi, ym(200:end), 'kind', 'everett', 'degree', 3, 'tdegree', 1, 'delay', 0);
  check(k.used == numel(xi) - head, 'from inside a loop: used %d of %d', k.used, numel(xi));
  check(max(abs(k.terms - p.terms)) < 0.01, 'from inside a loop: terms %s', mat2str(k.terms, 6));
end

function t_everett_save_load(ctx)
  % the same doubles back, delay included; the model runs the same
  e = e3();
  e.terms = [-0 5e-324 1/3 -2.5e-300 7e300 0.1];
  e.y_lo = pi;
  e.delay = 3;
  file = fullfile(ctx.tmp, 'everett.hyst');
  hyst_model_save(file, e);
  m = hyst_model_load(file);
  check(isequal(fieldnames(m), {'kind'; 'lo'; 'hi'; 'y_lo'; 'degree'; 'terms'; 'delay'}), 'fields');
  check(isequal(typecast([m.terms m.y_lo m.lo m.hi], 'uint64'), ...
                typecast([e.terms e.y_lo e.lo e.hi], 'uint64')), 'not the same doubles');
  check(strcmp(m.kind, 'everett') && m.degree == 3 && m.delay == 3, 'kind, degree, delay');
  e = e3();
  hyst_model_save(file, e);
  x = signal(2000, e.lo, e.hi, 14);
  check(isequal(hyst_sim(hyst_model_load(file), x), hyst_sim(e, x)), 'simulations differ');
  text = fileread(file);
  % the host tool's text (tools/model_text): every key, the delay too
  check(~isempty(strfind(text, sprintf('\ndelay 0\n'))) && ...
        ~isempty(strfind(text, sprintf('\nkind everett\n'))), 'text: %s', text);
  % the format's example, as the host tool writes it
  write_lines(file, {'hyst-model-text 1', '# comment lines as now', 'kind everett', 'lo 0', ...
                     'hi 3.6000000000000001', 'y_lo -0.035382239014971697', 'delay 3', ...
                     'degree 2', 'terms 0.61 0.02 -0.1'});
  m = hyst_model_load(file);
  check(m.hi == 3.6 && m.y_lo == -0.035382239014971697 && isequal(m.terms, [0.61 0.02 -0.1]) && ...
        m.delay == 3 && m.degree == 2, 'the example');
end

function t_everett_load_rejects(ctx)
  file = fullfile(ctx.tmp, 'bad_everett.txt');
  good = {'hyst-model-text 1', 'kind everett', 'lo 0', 'hi 3.6', 'y_lo 0', 'degree 2', ...
          'terms 0.61 0.02 -0.1'};
  bad = {
    [good {'coeffs 1 2'}], ':8: field 1: coeffs is not a key of kind everett'
    {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi 40', 'terms 1', 'coeffs 1 2'}, ':5: field 1: terms is not a key of kind poly'
    {'hyst-model-text 1', 'kind poly', 'y_lo 0', 'lo 0', 'hi 40', 'coeffs 1 2'}, ':3: field 1: y_lo is not a key of kind poly'
    {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi 40', 'coeffs 1 2', 'degree 1'}, ':6: field 1: degree is not a key of kind poly'
    good([1:4 6 7]), 'the key y_lo is missing'
    good([1:5 7]), 'the key degree is missing'
    good(1:6), 'the key terms is missing'
    [good(1:5) {'degree 5'} good(7)], ':6: field 2: ''5'' is not a degree in 1..4'
    [good(1:5) {'degree 1.5'} good(7)], ':6: field 2: ''1.5'' is not a degree in 1..4'
    [good(1:6) {'terms 1 2'}], ':7: field 4 is missing: terms needs 3 numbers for degree 2'
    [good(1:6) {'terms 1 NaN 2'}], ':7: field 3: ''NaN'' is not a finite number'
    [good(1:4) {'y_lo Inf'} good(6:7)], ':5: field 2: ''Inf'' is not a finite number'
    [{'hyst-model-text 1', 'kind preisach'} good(3:7)], ':2: field 2: kind must be ''poly'', ''everett'', ''everett_grid'' or ''spline'''
  };
  expect_load_errors(file, bad);
end

function yd = walk(lo, hi, n)
  % a random walk with jumps (one in ten) over [lo, hi], ends included
  yd = zeros(n, 1);
  v = (lo + hi) / 2;
  for i = 1:n
    if rand() < 0.1
      v = lo + (hi - lo) * rand();
    else
      v = min(max(v + (hi - lo) * (rand() - 0.5) / 10, lo), hi);
    end
    yd(i) = v;
  end
end

function t_everett_inv(~)
  % for E of degrees 2, 3 and 4: hyst_sim(hyst_inv(y_d)) = y_d on a random
  % walk over the major loop's output range (1e-9 of the range in double,
  % 2e-5 in single); on small steps up and down through many turning points
  % the drive never moves against the desired output
  es = everett_examples();
  rand('state', 15);
  for k = 1:numel(es)
    e = es{k};
    range = e_value(e, e.hi, e.lo);
    yd = walk(e.y_lo, e.y_lo + range, 3000);
    x = hyst_inv(e, yd);
    check(all(x >= e.lo & x <= e.hi), 'degree %d: a drive outside the domain', e.degree);
    err = max(abs(hyst_sim(e, x) - yd));
    check(err <= 1e-9 * range, 'degree %d, double: |sim(inv(y)) - y| up to %g', e.degree, err);
    xs = hyst_inv(e, single(yd));
    check(strcmp(class(xs), 'single'), 'class %s', class(xs));
    err = max(abs(double(hyst_sim(e, xs)) - double(single(yd))));
    check(err <= 2e-5 * range, 'degree %d, single: |sim(inv(y)) - y| up to %g', e.degree, err);

    up = true(20000, 1);
    for i = 2:numel(up)
      up(i) = xor(up(i - 1), rand() < 0.02);
    end
    yd = e.y_lo + range * (0.5 + 2e-6 * cumsum(2 * up - 1));
    for cls = {'double', 'single'}
      d = diff(double(hyst_inv(e, cast(yd, cls{1}))));
      check(all(d(up(2:end)) >= 0) && all(d(~up(2:end)) <= 0), ...
            'degree %d, %s: the drive moved against the desired output', e.degree, cls{1});
      check(nnz(d > 0) > 1000 && nnz(d < 0) > 1000, 'degree %d, %s: the drive hardly moved', ...
            e.degree, cls{1});
    end
  end
  e = e3();
  [x, st] = hyst_inv(e, [e.y_lo + e_value(e, e.hi, e.lo) + 1, e.y_lo - 1]);
  check(isequal(x, [e.hi, e.lo]) && st == 1, 'clamped: drive %s, status %d', mat2str(x), st);
end

% ---- the asymmetric kind's tabulated compensator ('intervals', 'rows') ----

function same = bits_equal(a, b)
  % the same numbers bit for bit (and the same class)
  same = strcmp(class(a), class(b)) && isequal(size(a), size(b));
  if same && isa(a, 'double')
    same = isequal(typecast(a(:), 'uint64'), typecast(b(:), 'uint64'));
  elseif same
    same = isequal(typecast(a(:), 'uint32'), typecast(b(:), 'uint32'));
  end
end

function t_everett_inv_table_bitexact(ctx)
  % hyst_inv(e, y, 'intervals', N[, 'rows', R]): the tabulated compensator
  % firmware runs (hyst_*_curve_everett_inverse_table), bit for bit against
  % the C library (hyst_ref) in double and single, with the same status and
  % init's measured error; 'rows' defaults to the library's
  % HYST_EVERETT_INV_ROWS (hyst_ref's default); without 'intervals' the
  % solved compensator, also bit for bit
  e = e3();
  range = e_value(e, e.hi, e.lo);
  rand('state', 21);
  yd = walk(e.y_lo, e.y_lo + range, 3000);
  yd(700) = e.y_lo + range + 1;       % clamped
  yd(1400) = e.y_lo - 1;
  yd(2100) = NaN;                     % ignored
  [x, st, ~, err] = hyst_inv(e, yd, 'intervals', 32);
  [xc, stc, errc] = run_ref(ctx, 'inv', 'double', e, yd, 'intervals=32');
  check(bits_equal(x, xc), 'f64 differs from hyst_ref in %d samples', nnz(x ~= xc));
  check(st == stc && st == -7, 'status %d, hyst_ref %d (-7 expected: a NaN sample)', st, stc);
  check(err == errc && err > 0, 'measured error %.17g, hyst_ref %.17g', err, errc);
  config = hyst_mex('config');
  check(isequal(x, hyst_inv(e, yd, 'intervals', 32, 'rows', config.everett_inv_rows)), ...
        '''rows'' %d differs from the default', config.everett_inv_rows);
  % another table: rows and intervals reach the library
  [x5, st5, ~, err5] = hyst_inv(e, yd, 'intervals', 12, 'rows', 5);
  [xc, stc, errc] = run_ref(ctx, 'inv', 'double', e, yd, 'intervals=12', 'rows=5');
  check(bits_equal(x5, xc) && st5 == stc && err5 == errc, 'f64, 5 rows of 12 intervals differ');
  check(any(x5 ~= x) && err5 ~= err, 'another table changed nothing');
  % single: hyst_f32_*, a row vector
  ys = single(yd');
  for t = {{'intervals', 32}, {'intervals', 64, 'rows', 7}}
    opts = t{1};
    keys = {sprintf('intervals=%d', opts{2})};
    if numel(opts) > 2
      keys{2} = sprintf('rows=%d', opts{4});
    end
    [xs, st, ~, err] = hyst_inv(e, ys, opts{:});
    [xc, stc, errc] = run_ref(ctx, 'inv', 'single', e, ys, keys{:});
    check(bits_equal(xs, xc), 'f32 (%s) differs in %d samples', strjoin(keys, ' '), nnz(xs ~= xc));
    check(st == stc && err == errc && err > 0, 'f32 (%s): status %d / %d, error %g / %g', ...
          strjoin(keys, ' '), st, stc, err, errc);
  end
  check(any(double(xs) ~= hyst_inv(e, yd', 'intervals', 64, 'rows', 7)), 'single equals double');
  % the solved compensator stays the default
  [xe, st, ~, err] = hyst_inv(e, yd);
  [xc, stc, errc] = run_ref(ctx, 'inv', 'double', e, yd);
  check(bits_equal(xe, xc) && st == stc && err == 0 && errc == 0, 'the solved compensator');
  check(any(xe ~= x), 'the table equals the solved compensator');
  % bounded memory and a deadband reach the library as well
  [xb, st] = hyst_inv(e, yd, 'intervals', 32, 'capacity', 3, 'deadband', 1e-3 * range);
  [xc, stc] = run_ref(ctx, 'inv', 'double', e, yd, 'intervals=32', 'cap=3', ...
                      sprintf('deadband=%.17g', 1e-3 * range));
  check(bits_equal(xb, xc) && st == stc, 'capacity 3 and a deadband: differs');
  check(any(xb ~= x), 'capacity 3 and a deadband changed nothing');
end

function t_everett_inv_table_error(~)
  % the default table (HYST_EVERETT_INV_ROWS x HYST_EVERETT_INV_INTERVALS)
  % against the exact (solved) compensator, for E of degrees 3, 2 and 4:
  % sweeping up from rest, each drive is one table evaluation from an exact
  % turning point: within init's measured error (down again from the top,
  % whose drive is the table's, within twice that), in double and single; a
  % random walk with jumps within 1e-5 of the drive span in double and
  % single; the measured error within HYST_INV_TABLE_TOL
  config = hyst_mex('config');
  n = config.everett_inv_intervals;
  es = everett_examples();
  rand('state', 22);
  slack = 2^-38;                      % the solved compensator's own tolerance, 2^-40
  for k = 1:numel(es)
    e = es{k};
    span = e.hi - e.lo;
    range = e_value(e, e.hi, e.lo);
    up = e.y_lo + range * (0:2000)' / 2000;
    yd = [up; flipud(up)];
    [x, st, ~, err] = hyst_inv(e, yd, 'intervals', n);
    xe = hyst_inv(e, yd);
    check(st == 0, 'degree %d: status %d', e.degree, st);
    check(err > 0 && err <= config.inv_table_tol, 'degree %d: measured error %g', e.degree, err);
    d = abs(x - xe) / span;
    check(max(d(1:2001)) <= 1.01 * err + slack, 'degree %d, up: %g, measured %g', ...
          e.degree, max(d(1:2001)), err);
    check(max(d(2002:end)) <= 2 * (1.01 * err + slack), 'degree %d, down: %g, measured %g', ...
          e.degree, max(d(2002:end)), err);
    check(max(d) > 0, 'degree %d: the table equals the solved compensator', e.degree);
    % single: init's error holds the float arithmetic's rounding; against
    % the exact drive for the float desired outputs
    ys = single(yd);
    [xs, ~, ~, errs] = hyst_inv(e, ys, 'intervals', n);
    d = abs(double(xs) - hyst_inv(e, double(ys))) / span;
    check(max(d(1:2001)) <= 1.01 * errs + eps('single') && ...
          max(d(2002:end)) <= 2 * (1.01 * errs + eps('single')), ...
          'degree %d, single: up %g, down %g, measured %g', e.degree, max(d(1:2001)), ...
          max(d(2002:end)), errs);
    yd = walk(e.y_lo, e.y_lo + range, 3000);
    xe = hyst_inv(e, yd);
    d = max(abs(hyst_inv(e, yd, 'intervals', n) - xe)) / span;
    check(d <= 1e-5, 'degree %d, double: %g of the drive span', e.degree, d);
    [xs, ~, ~, errs] = hyst_inv(e, single(yd), 'intervals', n);
    d = max(abs(double(xs) - hyst_inv(e, double(single(yd))))) / span;
    check(d <= 1e-5, 'degree %d, single: %g of the drive span', e.degree, d);
    check(errs > 0 && errs <= config.inv_table_tol, 'degree %d, single: measured %g', ...
          e.degree, errs);
  end
end

function t_everett_inv_table_monotone(~)
  % small steps up and down through many turning points, and wider moves
  % across the table's intervals: the tabulated compensator's drive never
  % moves against the desired output, in double and single
  es = everett_examples();
  rand('state', 23);
  for k = 1:numel(es)
    e = es{k};
    range = e_value(e, e.hi, e.lo);
    up = true(20000, 1);
    for i = 2:numel(up)
      up(i) = xor(up(i - 1), rand() < 0.02);
    end
    step = 2e-6 * ones(size(up));
    step(rand(size(up)) < 0.01) = 1e-2;
    yd = e.y_lo + range * min(max(0.5 + cumsum((2 * up - 1) .* step), 0), 1);
    for cls = {'double', 'single'}
      yc = cast(yd, cls{1});
      dy = diff(double(yc));
      d = diff(double(hyst_inv(e, yc, 'intervals', 32, 'rows', 16)));
      check(all(d(dy > 0) >= 0) && all(d(dy < 0) <= 0) && all(d(dy == 0) == 0), ...
            'degree %d, %s: the drive moved against the desired output', e.degree, cls{1});
      check(nnz(d > 0) > 1000 && nnz(d < 0) > 1000, 'degree %d, %s: the drive hardly moved', ...
            e.degree, cls{1});
    end
  end
end

function t_everett_inv_table_arguments(~)
  % 'rows' only with 'intervals' and the asymmetric kind; rows 3..4096 and
  % intervals 1..2^20 (0: solved) refused with the range in the message,
  % before anything is allocated (the largest table of out-of-range sizes
  % would not fit); the gateway checks them as well
  e = e3();
  y = e.y_lo + [0.1 0.5 0.2];
  msg = @(varargin) error_message(@() hyst_inv(varargin{:}));
  expect_error('hyst:usage', @() hyst_inv(paper_f0(), 1, 'intervals', 256, 'rows', 16));
  check(~isempty(strfind(msg(paper_f0(), 1, 'intervals', 256, 'rows', 16), 'asymmetric')), ...
        'poly: %s', msg(paper_f0(), 1, 'intervals', 256, 'rows', 16));
  for args = {{'rows', 16}, {'rows', 16, 'intervals', 0}}
    expect_error('hyst:usage', @() hyst_inv(e, y, args{1}{:}));
    check(~isempty(strfind(msg(e, y, args{1}{:}), 'needs ''intervals''')), 'no intervals: %s', ...
          msg(e, y, args{1}{:}));
  end
  for rows = {2, 4097, 2.5, -1, NaN, Inf, [16 16], '16', 1i + 16}
    expect_error('hyst:usage', @() hyst_inv(e, y, 'intervals', 32, 'rows', rows{1}));
    check(~isempty(strfind(msg(e, y, 'intervals', 32, 'rows', rows{1}), '3..4096')), ...
          'rows %s: %s', num2str(rows{1}), msg(e, y, 'intervals', 32, 'rows', rows{1}));
  end
  for intervals = {2^20 + 1, -1, 0.5, NaN, [32 32], '32'}
    for m = {e, paper_f0()}
      expect_error('hyst:usage', @() hyst_inv(m{1}, y, 'intervals', intervals{1}));
      check(~isempty(strfind(msg(m{1}, y, 'intervals', intervals{1}), '1..1048576')), ...
            'intervals %s: %s', num2str(intervals{1}), msg(m{1}, y, 'intervals', intervals{1}));
    end
  end
  text = msg(e, y, 'intervals', 2^20 + 1, 'rows', 4096);
  check(~isempty(strfind(text, '1..1048576')), 'the largest sizes: %s', text);
  expect_error('hyst:usage', @() hyst_sim(e, 1, 'rows', 16));
  expect_error('hyst:usage', @() hyst_sim(e, 1, 'intervals', 16));
  % the gateway: intervals and rows after the deadband, checked in range
  p = {e.degree, e.lo, e.hi, e.y_lo, e.terms, y, 2048, 0};
  x = hyst_mex('inv_everett', p{:}, 32, 16);
  check(isequal(x, hyst_inv(e, y, 'intervals', 32)), 'hyst_mex inv_everett');
  expect_error('hyst:usage', @() hyst_mex('inv_everett', p{:}));
  expect_error('hyst:usage', @() hyst_mex('inv_everett', p{:}, 32));
  check(~isempty(strfind(error_message(@() hyst_mex('inv_everett', p{:}, 2^20 + 1, 4096)), ...
                         'intervals must be a whole number in 0..1048576')), 'gateway, intervals');
  check(~isempty(strfind(error_message(@() hyst_mex('inv_everett', p{:}, 2^20, 4097)), ...
                         'rows must be a whole number in 3..4096')), 'gateway, rows');
  check(~isempty(strfind(error_message(@() hyst_mex('inv_everett', p{:}, 32, 2)), ...
                         'rows must be a whole number in 3..4096')), 'gateway, rows 2');
end

% ---- firmware headers (hyst_header) ----

function e = header_everett()
  % the asymmetric model of the Python package's header tests
  e = struct('kind', 'everett', 'degree', 3, 'lo', 0, 'hi', 40, 'y_lo', 0.5, ...
             'terms', [3 1 0 2 -0.5 0.4]);
end

function rest = after_first_line(text)
  rest = text(find(text == sprintf('\n'), 1):end);
end

function t_header_equals_cli(ctx)
  % hyst_header's text is hyst header's, but for the first line (the
  % generator's name): a polynomial f0 (with a delay) and an E, without and
  % with the compensator's table, of the default size and another
  m = paper_f0();
  m.delay = 2;
  e = header_everett();
  cases = {m, {}, ''
           m, {'compensator', true}, '--compensator'
           m, {'compensator', true, 'intervals', 64}, '--compensator --intervals 64'
           e, {}, ''
           e, {'compensator', true}, '--compensator'
           e, {'compensator', true, 'intervals', 16, 'rows', 8}, ...
           '--compensator --intervals 16 --rows 8'};
  file = fullfile(ctx.tmp, 'header.hyst');
  for k = 1:size(cases, 1)
    hyst_model_save(file, cases{k, 1});
    run_cli(ctx, sprintf('header --model "%s" --dir "%s" %s comp 2>&1', file, ctx.tmp, ...
                         cases{k, 3}));
    cli_text = fileread(fullfile(ctx.tmp, 'comp.h'));
    text = hyst_header(cases{k, 1}, 'comp', cases{k, 2}{:});
    check(strcmp(after_first_line(text), after_first_line(cli_text)), ...
          'case %d (%s): the text differs from hyst header''s', k, cases{k, 3});
    check(strncmp(text, '/* Generated by the MATLAB/Octave package hyst', 46), ...
          'case %d: first line %s', k, strtok(text, sprintf('\n')));
    check(isempty(cases{k, 3}) == isempty(strfind(text, 'comp_seal')), 'case %d: the table', k);
  end
  check(~isempty(strfind(hyst_header(m, 'comp'), sprintf('\n * 2 samples later'))), 'the delay');
end

function [numbers, crc, max_err] = header_table(text, name, f32)
  % the numbers and the seal of one variant's table in a header's text
  part = strsplit(text, sprintf('#else\n')){1 + f32};
  body = regexp(part, [name '_table\[[^]]*\] = \{(.*?)\};'], 'tokens', 'once'){1};
  numbers = str2double(strsplit(strrep(strrep(body, 'f', ''), sprintf('\n'), ''), ','))';
  seal = regexp(part, [name '_seal = \{0x([0-9A-F]{8})ul, ([^}]*)\}'], 'tokens', 'once');
  crc = hex2dec(seal{1});
  max_err = str2double(seal{2});
end

function t_header_tables(~)
  % the tables in the header are the library's (hyst_mex inv_table and
  % inv_table_everett), bit for bit, with their seals; the double table is
  % the compensator hyst_inv runs (the same measured error); the float table
  % is built from the model's numbers rounded to float; the float and double
  % seals differ
  e = header_everett();
  p = paper_f0();
  cases = {e, {'intervals', 16, 'rows', 8}, ...
           @(cls) hyst_mex('inv_table_everett', e.degree, e.lo, e.hi, e.y_lo, e.terms, 16, 8, cls)
           p, {'intervals', 64}, @(cls) hyst_mex('inv_table', p.coeffs, p.lo, p.hi, 64, cls)};
  for k = 1:size(cases, 1)
    text = hyst_header(cases{k, 1}, 'comp', 'compensator', true, cases{k, 2}{:});
    build = cases{k, 3};
    [t64, crc64, err64, ~, inv_err] = build('double');
    [t32, crc32, err32] = build('single');
    [n64, c64, e64] = header_table(text, 'comp', false);
    [n32, c32, e32] = header_table(text, 'comp', true);
    check(bits_equal(n64, t64) && c64 == crc64 && e64 == err64, 'case %d: the double table', k);
    check(bits_equal(single(n32), t32) && c32 == crc32 && e32 == err32, ...
          'case %d: the float table', k);
    check(c32 ~= c64 && any(double(t32) ~= t64), 'case %d: the float and double seals', k);
    check(err64 >= inv_err && err64 <= inv_err * (1 + 2^-23), 'case %d: seal %g, measured %g', ...
          k, err64, inv_err);
    [~, ~, ~, err] = hyst_inv(cases{k, 1}, 0.6, cases{k, 2}{:});
    check(err == inv_err, 'case %d: measured %.17g, hyst_inv %.17g', k, inv_err, err);
  end
  % the float table of the numbers rounded to float is the same table
  t = hyst_mex('inv_table', double(single(p.coeffs)), 0, 40, 64, 'single');
  check(bits_equal(t, hyst_mex('inv_table', p.coeffs, 0, 40, 64, 'single')), 'float rounding');
end

function t_header_file(ctx)
  % 'file' writes exactly TEXT (replacing a file); into a directory that does
  % not exist, or onto a directory, it raises hyst:model_file and leaves
  % nothing behind
  file = fullfile(ctx.tmp, 'written.h');
  write_lines(file, {'an older file'});
  text = hyst_header(header_everett(), 'model_e', 'file', file);
  check(strcmp(fileread(file), text), 'the file is not TEXT');
  info = dir(file);
  check(info.bytes == numel(text), '%d bytes, TEXT has %d', info.bytes, numel(text));
  before = dir(ctx.tmp);
  missing = fullfile(ctx.tmp, 'no_such_dir', 'model.h');
  expect_error('hyst:model_file', @() hyst_header(paper_f0(), 'm', 'file', missing));
  check(~exist(fileparts(missing), 'dir'), 'the directory was made');
  folder = fullfile(ctx.tmp, 'a_dir.h');
  mkdir(folder);
  expect_error('hyst:model_file', @() hyst_header(paper_f0(), 'm', 'file', folder));
  check(exist(folder, 'dir') == 7, 'the directory is gone');
  rmdir(folder);
  check(isequal(sort({dir(ctx.tmp).name}), sort({before.name})), 'a file was left behind');
end

function t_header_arguments(~)
  % NAME a C identifier; 'intervals' and 'rows' only with 'compensator';
  % 'rows' only for kind everett; sizes in range (before the gateway
  % allocates; the gateway checks them as well); the model as the host tool
  % takes it
  m = paper_f0();
  e = header_everett();
  msg = @(varargin) error_message(@() hyst_header(varargin{:}));
  names = {'1abc', 'a-b', '', blanks(0), 'a b', char([99 97 102 233]), 3, repmat('a', 1, 200), {'m'}, ...
           ['ab'; 'cd']};
  for name = names
    expect_error('hyst:usage', @() hyst_header(m, name{1}));
  end
  check(~isempty(strfind(msg(m, 'a-b'), 'C identifier')), 'name: %s', msg(m, 'a-b'));
  check(~isempty(strfind(hyst_header(m, '_x9'), 'hyst_poly_t _x9 = {')), 'the name _x9');
  expect_error('hyst:usage', @() hyst_header(m, 'm', 'compensator', true, 'rows', 8));
  check(~isempty(strfind(msg(m, 'm', 'compensator', true, 'rows', 8), 'asymmetric')), ...
        'rows for f0: %s', msg(m, 'm', 'compensator', true, 'rows', 8));
  for args = {{'intervals', 64}, {'rows', 8}, {'intervals', 64, 'compensator', false}}
    expect_error('hyst:usage', @() hyst_header(e, 'm', args{1}{:}));
    check(~isempty(strfind(msg(e, 'm', args{1}{:}), 'need ''compensator''')), 'no compensator');
  end
  for intervals = {0, 2^20 + 1, 0.5, -1, NaN, '64', [8 8]}
    for model = {m, e}
      expect_error('hyst:usage', @() hyst_header(model{1}, 'm', 'compensator', true, ...
                                                 'intervals', intervals{1}));
      check(~isempty(strfind(msg(model{1}, 'm', 'compensator', true, 'intervals', intervals{1}), ...
                             '1..1048576')), 'intervals %s', num2str(intervals{1}));
    end
  end
  for rows = {2, 4097, 8.5}
    expect_error('hyst:usage', @() hyst_header(e, 'm', 'compensator', true, 'rows', rows{1}));
  end
  expect_error('hyst:usage', @() hyst_header(m, 'm', 'compensator', 'yes'));
  expect_error('hyst:usage', @() hyst_header(m, 'm', 'compensator', NaN));
  expect_error('hyst:usage', @() hyst_header(m, 'm', 'file', 3));
  expect_error('hyst:usage', @() hyst_header(m, 'm', 'firmware', true));
  expect_error('hyst:usage', @() hyst_header(struct('coeffs', 1:11, 'lo', 0, 'hi', 1), 'm'));
  expect_error('hyst:usage', @() hyst_header(struct('coeffs', [1 NaN], 'lo', 0, 'hi', 1), 'm'));
  bad = m;
  bad.delay = -1.5;
  expect_error('hyst:usage', @() hyst_header(bad, 'm'));
  % a sub-sample delay is a model file's (delay 1.5): the header states it
  late = m;
  late.delay = 1.5;
  check(~isempty(strfind(hyst_header(late, 'm'), sprintf('\n * 1.5 samples later'))), ...
        'delay 1.5 in the header');
  bad = e;
  bad.terms = [0.61 0.02 -1];
  bad.degree = 2;
  expect_error('hyst:ERR_NOT_MONOTONE', @() hyst_header(bad, 'm'));
  check(~isempty(strfind(msg(bad, 'm'), 'hyst_header: ')), 'not monotone: %s', msg(bad, 'm'));
  % the gateway: the table's size and class checked
  p = {m.coeffs, m.lo, m.hi};
  check(~isempty(strfind(error_message(@() hyst_mex('inv_table', p{:}, 0, 'double')), ...
                         'intervals must be a whole number in 1..1048576')), 'gateway, intervals');
  check(~isempty(strfind(error_message(@() hyst_mex('inv_table_everett', e.degree, e.lo, e.hi, ...
                                                    e.y_lo, e.terms, 2^20, 4097, 'double')), ...
                         'rows must be a whole number in 3..4096')), 'gateway, rows');
  expect_error('hyst:usage', @() hyst_mex('inv_table', p{:}, 64, 'int8'));
  expect_error('hyst:usage', @() hyst_mex('inv_table', p{:}, 64));
  expect_error('hyst:ERR_NOT_INCREASING', @() hyst_mex('inv_table', [-1 0], 0, 1, 8, 'double'));
end

% ---- the creep term (hyst/creep.h, docs/creep.md) ----

function m = creep_plant()
  % tests/cli/creep.sh's plant: Eq. 20 on [0, 40] V, delay 3, one lag of
  % 2000 samples weighing 0.05
  m = paper_f0();
  m.delay = 3;
  m.creep_tau = 2000;
  m.creep_weight = 0.05;
end

function e = creep_everett()
  % an asymmetric model with two lags, one of negative weight
  e = header_everett();
  e.delay = 2;
  e.creep_tau = [300 5000];
  e.creep_weight = [0.02 -0.01];
end

function m = creep_poly()
  % f0 on a domain that does not start at 0 (the lags rest at lo), four lags
  m = paper_f0();
  m.lo = 5;
  m.delay = 0;
  m.creep_tau = [1 50 700.5 1e6];
  m.creep_weight = [0.01 -0.02 0.03 0.5];
end

function v = read_numbers(text)
  v = str2double(strsplit(strtrim(text), sprintf('\n')))';
end

function write_numbers(file, v)
  fid = fopen(file, 'w');
  fprintf(fid, '%.17g\n', v);
  fclose(fid);
end

function same = cli_model_equal(ctx, command, file, in, out, delay)
  % hyst COMMAND --model FILE (sim or inv) over the numbers in gives out,
  % bit for bit (17 digits), sim's output delay samples later
  fin = fullfile(ctx.tmp, 'cli_model_in.txt');
  write_numbers(fin, in);
  c = read_numbers(run_cli(ctx, sprintf('%s --model "%s" --digits 17 "%s" 2>/dev/null', command, ...
                                        file, fin)));
  same = isequal(c(delay + 1:end), out(1:end - delay));
end

function t_creep_sim_inv_equal_cli(ctx)
  % a model with a creep term runs bit for bit as hyst sim --model (whose
  % output comes delay samples later) and its compensator as hyst inv
  % --model; the compensator gives sim's inputs back (clamped)
  file = fullfile(ctx.tmp, 'creep.hyst');
  models = {creep_plant(), creep_everett(), creep_poly()};
  for k = 1:numel(models)
    m = models{k};
    hyst_model_save(file, m);
    x = signal(3000, m.lo, m.hi, 20 + k);
    [y, st] = hyst_sim(m, x);
    check(st == 1, 'model %d: status %d (1: clamped samples)', k, st);
    d = hyst_model_load(file).delay;
    check(d == m.delay && cli_model_equal(ctx, 'sim', file, x, y, d), ...
          'model %d: sim differs from hyst sim --model', k);
    xd = hyst_inv(m, y);
    check(cli_model_equal(ctx, 'inv', file, y, xd, 0), 'model %d: inv differs from hyst inv --model', k);
    err = max(abs(xd - min(max(x, m.lo), m.hi)));
    check(err < 1e-9 * (m.hi - m.lo), 'model %d: |inv(sim(x)) - x| up to %g', k, err);
  end
end

function t_creep_sum_of_lags(~)
  % the model's output is the hysteresis model's plus the library's creep
  % (hyst_mex creep) of the inputs as the model took them (clamped), in
  % double and in single; the creep alone is the lag of its definition,
  % strictly causal, a NaN sample ignored (status -7)
  m = creep_poly();
  bare = rmfield(m, {'creep_tau', 'creep_weight'});
  for cls = {'double', 'single'}
    x = cast(signal(3000, m.lo, m.hi, 30), cls{1});
    c = hyst_mex('creep', m.creep_tau, m.creep_weight, m.lo, min(max(x, m.lo), m.hi));
    y = hyst_sim(m, x);
    check(strcmp(class(c), cls{1}) && isequal(y, hyst_sim(bare, x) + c), '%s: not the sum', ...
          cls{1});
    check(any(y ~= hyst_sim(bare, x)), '%s: the creep term changed nothing', cls{1});
  end
  tau = [5 300];
  w = [0.7 -0.2];
  u = signal(2000, -1, 3, 31);
  [c, st] = hyst_mex('creep', tau, w, 0.5, u);
  s = [0.5 0.5];
  ref = zeros(size(u));
  for k = 1:numel(u)
    ref(k) = w * s';
    s = s + (u(k) - s) ./ tau;
  end
  check(max(abs(c - ref)) < 1e-12 && st == 0, 'the lag: %g from its definition', ...
        max(abs(c - ref)));
  check(abs(c(1) - 0.5 * sum(w)) < 1e-15, 'not causal: c(1) = %g', c(1));
  u(7) = NaN;
  [c2, st] = hyst_mex('creep', tau, w, 0.5, u);
  check(st == -7 && c2(7) == c(7) && c2(8) == c(7), 'a NaN sample');
end

function t_creep_save_load(ctx)
  % written and read back: the same doubles, the host tool's creep lines
  % after the model's; the host tool's file (hyst fit --save) read, its
  % creep lines written back as they were; none without a creep term
  file = fullfile(ctx.tmp, 'creep_rt.hyst');
  models = {creep_plant(), creep_everett(), creep_poly()};
  for k = 1:numel(models)
    hyst_model_save(file, models{k});
    m = hyst_model_load(file);
    check(isequal(typecast([m.creep_tau m.creep_weight], 'uint64'), ...
                  typecast([models{k}.creep_tau models{k}.creep_weight], 'uint64')), ...
          'model %d: not the same creep term', k);
    lines = strsplit(strtrim(fileread(file)), sprintf('\n'));
    check(strcmp(lines{end - 2}, ['# creep: the output plus sum of creep_weight[k] s_k, s_k ' ...
                                  'the input lagged with time constant creep_tau[k] samples ' ...
                                  '(from lo at rest)']) && ...
          strncmp(lines{end - 1}, 'creep_tau ', 10) && strncmp(lines{end}, 'creep_weight ', 13), ...
          'model %d: the creep lines', k);
    x = signal(1000, m.lo, m.hi, 40 + k);
    check(isequal(hyst_sim(m, x), hyst_sim(models{k}, x)), 'model %d: runs differently', k);
  end
  cli_file = fullfile(ctx.tmp, 'creep_cli.hyst');
  data = fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat');
  run_cli(ctx, sprintf('fit --degree 3 --skip 350 --delay 1 --xcol 1 --ycol 5 --save "%s" "%s" 2>&1', ...
                       cli_file, data));
  c = hyst_model_load(cli_file);
  check(isfield(c, 'creep_tau') && c.creep_tau == 5000, 'hyst fit --save''s creep term');
  hyst_model_save(file, c);
  a = strsplit(strtrim(fileread(file)), sprintf('\n'));
  b = strsplit(strtrim(fileread(cli_file)), sprintf('\n'));
  check(isequal(a(end - 2:end), b(end - 2:end)), 'the creep lines differ from the host tool''s');
  hyst_model_save(file, paper_f0());
  check(isempty(strfind(fileread(file), 'creep')) && ~isfield(hyst_model_load(file), 'creep_tau'), ...
        'a creep term without one');
end

function t_creep_load_rejects(ctx)
  % a broken creep term is refused in the host tool's words, naming the
  % file, the line and the field: hyst_model_load's message after its name
  % is hyst sim's after 'hyst sim: '
  file = fullfile(ctx.tmp, 'bad_creep.hyst');
  good = {'hyst-model-text 1', 'kind poly', 'lo 0', 'hi 1', 'coeffs 1 0'};
  bad = {
    {'creep_tau 100'}, ':6: field 1: creep_tau needs creep_weight too (creep: both or neither)'
    {'creep_weight 0.1'}, ':6: field 1: creep_weight needs creep_tau too (creep: both or neither)'
    {'creep_tau 100 1000', 'creep_weight 0.5'}, ...
    ':7: field 3 is missing: creep_weight needs 2 numbers, one per creep_tau'
    {'creep_tau 0.5', 'creep_weight 0.5'}, ...
    ':6: field 2: ''0.5'' is not a time constant of at least 1 sample'
    {'creep_tau 100 -3', 'creep_weight 0.5 1'}, ...
    ':6: field 3: ''-3'' is not a time constant of at least 1 sample'
    {'creep_tau 1 2 3 4 5', 'creep_weight 1 1 1 1 1'}, ...
    ':6: field 6: one too many: creep_tau needs 1 to 4 numbers (one per creep term)'
    {'creep_tau 1', 'creep_weight 1 1 1 1 1'}, ...
    ':7: field 6: one too many: creep_weight needs 1 to 4 numbers (one per creep term)'
    {'creep_tau', 'creep_weight 1'}, ...
    ':6: field 2 is missing: creep_tau needs 1 to 4 numbers (one per creep term)'
    {'creep_tau 10', 'creep_weight nan'}, ':7: field 2: ''nan'' is not a finite number'
    {'creep_tau 10', 'creep_weight 0.1 x'}, ':7: field 3: ''x'' is not a finite number'
  };
  for k = 1:size(bad, 1)
    write_lines(file, [good bad{k, 1}]);
    msg = error_message(@() hyst_model_load(file));
    expect_error('hyst:model_file', @() hyst_model_load(file));
    check(strcmp(msg, ['hyst_model_load: ' file bad{k, 2}]), 'case %d: message ''%s''', k, msg);
    [rc, out] = system(sprintf('echo 0.5 | "%s" sim --model "%s" 2>&1', ctx.cli, file));
    check(rc ~= 0 && strcmp(strtrim(out), ['hyst sim: ' file bad{k, 2}]), ...
          'case %d: hyst sim says ''%s''', k, strtrim(out));
  end
  % either kind, the creep keys anywhere
  write_lines(file, {'hyst-model-text 1', 'creep_weight 0.25', 'kind everett', 'lo 0', 'hi 2', ...
                     'creep_tau 7', 'y_lo 1', 'degree 1', 'terms 2'});
  e = hyst_model_load(file);
  check(strcmp(e.kind, 'everett') && e.creep_tau == 7 && e.creep_weight == 0.25, ...
        'kind everett with a creep term');
end

function t_creep_header_equals_cli(ctx)
  % hyst_header's text is hyst header's but for the first line, the creep
  % block included (after the declaration, before the compensator's table)
  file = fullfile(ctx.tmp, 'creep_header.hyst');
  cases = {creep_plant(), {}, ''
           creep_plant(), {'compensator', true}, '--compensator'
           creep_everett(), {}, ''
           creep_everett(), {'compensator', true, 'intervals', 16, 'rows', 8}, ...
           '--compensator --intervals 16 --rows 8'
           creep_poly(), {}, ''};
  for k = 1:size(cases, 1)
    m = cases{k, 1};
    hyst_model_save(file, m);
    run_cli(ctx, sprintf('header --model "%s" --dir "%s" %s comp 2>&1', file, ctx.tmp, ...
                         cases{k, 3}));
    cli_text = fileread(fullfile(ctx.tmp, 'comp.h'));
    text = hyst_header(m, 'comp', cases{k, 2}{:});
    check(strcmp(after_first_line(text), after_first_line(cli_text)), ...
          'case %d (%s): the text differs from hyst header''s', k, cases{k, 3});
    check(~isempty(strfind(text, sprintf('#include "hyst/curve.h"\n#include "hyst/creep.h"\n'))) ...
          && ~isempty(strfind(text, sprintf('#define comp_CREEP_TERMS %du\n', ...
                                            numel(m.creep_tau)))), 'case %d: the creep block', k);
  end
end

function t_creep_fit(ctx)
  % hyst_fit's creep term is hyst fit --degree's (its option 'creep' as
  % --creep): the same model file, bit for bit (the constant with the creep
  % term's offset), the same creep line; 'none' and a time constant as the
  % tool; kind everett too
  data = fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat');
  d = load(data);
  cli_file = fullfile(ctx.tmp, 'creep_fit.hyst');
  cases = {'auto', '', 'poly', 5000
           'none', '--creep none', 'poly', []
           500, '--creep 500', 'poly', 500
           'auto', '--kind everett', 'everett', 5000};
  for k = 1:size(cases, 1)
    [creep, args, kind, tau] = cases{k, :};
    degree = 3 - strcmp(kind, 'everett');
    f = hyst_fit(d(:, 1), d(:, 5), 'kind', kind, 'degree', degree, 'skip', 350, 'delay', 1, ...
                 'creep', creep);
    out = run_cli(ctx, sprintf(['fit --degree %d --skip 350 --delay 1 --xcol 1 --ycol 5 %s ' ...
                                '--save "%s" "%s" 2>&1'], degree, args, cli_file, data));
    c = hyst_model_load(cli_file);
    check(isfield(f, 'creep_tau') == ~isempty(tau) && isfield(c, 'creep_tau') == ~isempty(tau), ...
          'case %d: a creep term or not', k);
    if strcmp(kind, 'everett')
      check(isequal([c.terms c.y_lo], [f.terms f.y_lo]), 'case %d: E differs', k);
    else
      check(isequal(c.coeffs, f.coeffs), 'case %d: f0 differs', k);
    end
    if isempty(tau)
      check(isempty(strfind(out, '# creep: tau')), 'case %d: hyst fit has a creep term', k);
      continue;
    end
    check(f.creep_tau == tau && c.creep_tau == tau && c.creep_weight == f.creep_weight, ...
          'case %d: creep %g, weight %.17g (hyst fit: %g, %.17g)', k, f.creep_tau, ...
          f.creep_weight, c.creep_tau, c.creep_weight);
    line = sprintf('# creep: tau %.6g samples, weight %.9g (hold-out rms %.6g; without it %.6g)', ...
                   f.creep_tau, f.creep_weight, f.creep.holdout_rms, f.creep.holdout_rms_without);
    check(~isempty(strfind(out, line)), 'case %d: no line ''%s''', k, line);
    % the model with it predicts the record better than without it
    x = d(351:end, 1);
    y = d(352:end, 5);
    e = hyst_sim(f, x)(1:end - 1) - y;
    e0 = hyst_sim(rmfield(f, {'creep_tau', 'creep_weight'}), x)(1:end - 1) - y;
    check(sqrt(mean(e .^ 2)) < sqrt(mean(e0 .^ 2)), 'case %d: no better with creep', k);
  end
end

function t_creep_errors(ctx)
  % a creep term the wrappers refuse (hyst:usage) or the library does
  % (hyst:<status>), before anything runs
  m = creep_plant();
  x = linspace(0, 40, 50)';
  bad = rmfield(m, 'creep_weight');
  expect_error('hyst:usage', @() hyst_sim(bad, x));
  bad = m;
  bad.creep_weight = [0.1 0.2];
  expect_error('hyst:usage', @() hyst_sim(bad, x));
  expect_error('hyst:usage', @() hyst_model_save(fullfile(ctx.tmp, 'b.hyst'), bad));
  expect_error('hyst:usage', @() hyst_header(bad, 'm'));
  bad = m;
  bad.creep_tau = 0.5;
  expect_error('hyst:ERR_ARG', @() hyst_sim(bad, x));
  expect_error('hyst:ERR_ARG', @() hyst_inv(bad, x));
  expect_error('hyst:usage', @() hyst_model_save(fullfile(ctx.tmp, 'b.hyst'), bad));
  bad = m;
  bad.creep_weight = Inf;
  expect_error('hyst:ERR_WEIGHTS', @() hyst_sim(bad, x));
  expect_error('hyst:usage', @() hyst_header(bad, 'm'));
  bad = m;
  bad.creep_tau = 1:5;
  bad.creep_weight = 1:5;
  expect_error('hyst:usage', @() hyst_sim(bad, x));
  expect_error('hyst:usage', @() hyst_model_save(fullfile(ctx.tmp, 'b.hyst'), bad));
  check(~exist(fullfile(ctx.tmp, 'b.hyst'), 'file'), 'a refused model was written');
  for c = {'sometimes', 0.5, 2e9, [100 200], true}
    expect_error('hyst:usage', @() hyst_fit(x, x, 'creep', c{1}));
  end
  expect_error('hyst:usage', @() hyst_mex('creep', [1 2], 1, 0, x));
  expect_error('hyst:ERR_ARG', @() hyst_mex('creep', 0.5, 1, 0, x));
end

function t_readers_agree(ctx)
  % every crafted file of tests/model_files (line ends, blanks, hexadecimal
  % and decimal-comma numbers, long lines, counts, limits, an empty domain):
  % hyst_model_load reads the values 'hyst header --model' reads (its
  % header, from the guard on, and the delay it states), or refuses the
  % file in the tool's words (python/tests/test_model_readers.py: the
  % Python package likewise)
  folder = fullfile(ctx.root, 'tests', 'model_files');
  files = dir(fullfile(folder, '*.hyst'));
  check(numel(files) >= 45, 'only %d crafted files', numel(files));
  out = fullfile(ctx.tmp, 'agree');
  mkdir(out);
  for k = 1:numel(files)
    name = files(k).name;
    file = fullfile(folder, name);
    [rc, said] = system(sprintf('"%s" header --model "%s" --dir "%s" m 2>&1', ctx.cli, file, out));
    said = strtrim(said);
    ok = strncmp(name, 'ok_', 3);
    check((rc == 0) == ok, '%s: hyst header says "%s"', name, said);
    if ~ok
      msg = error_message(@() hyst_model_load(file));
      mine = ['hyst header: ' msg(numel('hyst_model_load: ') + 1:end)];
      check(strcmp(mine, said), '%s: "%s" where hyst header says "%s"', name, msg, said);
      continue;
    end
    m = hyst_model_load(file);
    cli = fileread(fullfile(out, 'm.h'));
    delay = str2double(regexp(cli, 'follows its input\s+\*?\s*([0-9.e+]+) samples later', 'tokens', 'once'));
    check(m.delay == delay, '%s: delay %g, hyst header %g', name, m.delay, delay);
    mine = hyst_header(m, 'm');
    check(strcmp(mine(strfind(mine, '#ifndef'):end), cli(strfind(cli, '#ifndef'):end)), ...
          '%s: the header differs from that of hyst header', name);
  end
end

function t_fit_delay_saved(ctx)
  % hyst_fit's 'delay' is the model's: in its result, in the model file
  % hyst_model_save writes, read back by hyst_model_load and by hyst sim
  d = load(fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat'));
  f = hyst_fit(d(:, 1), d(:, 5), 'degree', 3, 'skip', 350, 'delay', 3, 'creep', 'none');
  check(isfield(f, 'delay') && f.delay == 3, 'hyst_fit returned no delay 3');
  file = fullfile(ctx.tmp, 'delayed.hyst');
  hyst_model_save(file, f);
  check(hyst_model_load(file).delay == 3, 'the saved model reads back another delay');
  [rc, out] = system(sprintf('printf "3\\n3\\n3\\n3\\n3\\n" | "%s" sim --model "%s"', ctx.cli, file));
  y = str2double(strsplit(strtrim(out)));
  check(rc == 0 && all(y(1:3) == y(1)) && y(4) ~= y(1), 'hyst sim does not delay by 3: %s', out);
end

function t_fit_chooses_as_cli(ctx)
  % 'degree', [] chooses with the hyst tool's own code (fit_select()): the
  % choice, the coefficients and the creep term 'hyst fit --kind tcm' prints
  data = fullfile(ctx.root, 'tests', 'data', 'piezo_major_loop.dat');
  d = load(data);
  f = hyst_fit(d(:, 1), d(:, 5), 'kind', 'poly', 'degree', [], 'delay', [], 'skip', 350);
  out = run_cli(ctx, ['fit --kind tcm --skip 350 --xcol 1 --ycol 5 "' data '"']);
  lines = strsplit(out, "\n");
  c = str2double(strsplit(lines{1}, ','));
  check(numel(c) == numel(f.coeffs) && all(abs(c - f.coeffs) <= 1e-14 * abs(f.coeffs) + 1e-300), ...
        'coefficients %s vs %s', lines{1}, mat2str(f.coeffs, 15));
  delay = str2double(regexp(out, '# delay (\d+) samples', 'tokens', 'once'));
  check(f.delay == delay, 'delay %g, hyst fit %g', f.delay, delay);
  tau = str2double(regexp(out, '# creep: tau (\d+) samples', 'tokens', 'once'));
  check(isfield(f, 'creep_tau') && f.creep_tau == tau, 'creep term, hyst fit: tau %g', tau);
  check(numel(f.candidates) == 81 && sum([f.candidates.chosen]) == 1, '%d candidates', ...
        numel(f.candidates));
  % the four kinds compared when 'kind' is not given: hyst fit's candidates
  % (324: 9 delays of 9 f0, 10 E, 2 grids and 15 splines)
  g = hyst_fit(d(:, 1), d(:, 5), 'degree', [], 'delay', [], 'skip', 350, 'creep', 'none');
  out = run_cli(ctx, ['fit --skip 350 --creep none --xcol 1 --ycol 5 "' data '"']);
  t = regexp(out, 'chosen by hold-out: degree (\d+), delay (\d+) \(kind (\w+)', 'tokens', 'once');
  kind = 'poly';
  if isfield(g, 'kind')
    kind = g.kind;
  end
  listed = numel(regexp(out, '^# candidate ', 'start', 'lineanchors'));
  check(numel(g.candidates) == 324 && listed == 324 && strcmp(kind, t{3}) && g.degree == str2double(t{1}) && ...
        g.delay == str2double(t{2}), 'the choice differs from hyst fit''s: %s', strjoin(t, ' '));
  % what the hold-out tested the choice on, as hyst fit prints it, and its
  % warning: this record's last third holds major loops only
  b = regexp(out, '# hold-out: (\d+) of its (\d+) inputs outside \[(\S+), (\S+)\]', 'tokens', ...
             'once');
  s = regexp(out, 'its inputs span (\S+) %[^\n]*, (\d+) reversals', 'tokens', 'once');
  e = g.excitation;
  check(e.beyond == str2double(b{1}) && e.holdout_n == str2double(b{2}) && ...
        e.fitted_lo == str2double(b{3}) && e.fitted_hi == str2double(b{4}) && ...
        abs(100 * e.span - str2double(s{1})) <= 5e-3 * 100 * e.span && ...
        e.minor == str2double(s{2}) && e.minor == 0, 'excitation %s, hyst fit %s; %s', ...
        mat2str([e.beyond e.holdout_n e.fitted_lo e.fitted_hi e.span e.minor]), ...
        strjoin(b, ' '), strjoin(s, ' '));
  % its outputs' noise floor, as hyst fit prints it (the record resolves it)
  n = regexp(out, '# hold-out noise floor: rms (\S+),', 'tokens', 'once');
  check(~isempty(n) && strcmp(sprintf('%.6g', e.noise), n{1}), 'noise floor %.6g, hyst fit %s', ...
        e.noise, strjoin(n, ' '));
  lastwarn('');
  hyst_fit(d(:, 1), d(:, 5), 'degree', [], 'delay', [], 'skip', 350, 'creep', 'none');
  [msg, id] = lastwarn();
  check(strcmp(id, 'hyst:excitation') && ~isempty(strfind(msg, 'no minor loop')), ...
        'warning %s: %s', id, msg);
end

function t_fit_validated_as_cli(ctx)
  % 'validate', [X2 Y2] makes the choice on a second record as 'hyst fit
  % --validate OTHER' does (fit_search() scoring every candidate on it): the
  % same model file, the validation RMS the tool prints; with a degree
  % given, the delay chosen on it; a constant validation record refused
  plant = fullfile(ctx.tmp, 'vplant.hyst');
  fid = fopen(plant, 'w');
  fprintf(fid, ['hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0\ndelay 12.5\n' ...
                'degree 2\nterms 3 -0.5 1\n']);
  fclose(fid);
  recs = {};
  for tops = {[40 30 40 20 40 35 40 25 40], [40 25 40 35 40 15 40]}
    x = [];
    for top = tops{1}
      x = [x, 0:0.05:top - 0.05, top:-0.05:0.05];  %#ok<AGROW>
    end
    x = [x, 0]';
    xf = fullfile(ctx.tmp, 'vx.txt');
    fid = fopen(xf, 'w');
    fprintf(fid, '%.17g\n', x);
    fclose(fid);
    y = str2double(strsplit(strtrim(run_cli(ctx, ['sim --model "' plant '" "' xf '"'])), "\n"))';
    y = y + 1e-3 * sin(0.37 * (1:numel(y)))';  % not the plant exactly
    rec = fullfile(ctx.tmp, sprintf('vrec%d.txt', numel(recs) + 1));
    fid = fopen(rec, 'w');
    fprintf(fid, '%.17g %.17g\n', [x, y]');
    fclose(fid);
    recs{end + 1} = struct('x', x, 'y', y, 'file', rec);  %#ok<AGROW>
  end
  a = recs{1};
  b = recs{2};
  cli_file = fullfile(ctx.tmp, 'validated_cli.hyst');
  out = run_cli(ctx, ['fit --validate "' b.file '" --save "' cli_file '" "' a.file '"']);
  said = regexp(out, '# chosen on \S*vrec2\.txt: [^\n]*: validation rms (\S+)\n', 'tokens', ...
                'once');
  check(~isempty(said), 'no validation line: %s', out);
  f = hyst_fit(a.x, a.y, 'validate', [b.x b.y]);
  oct_file = fullfile(ctx.tmp, 'validated_oct.hyst');
  hyst_model_save(oct_file, f);
  check(strcmp(fileread(oct_file), fileread(cli_file)), ...
        'hyst_fit(..., ''validate'') differs from hyst fit --validate');
  check(strcmp(sprintf('%.6g', f.validation_rms), said{1}), 'validation rms %.6g, hyst fit %s', ...
        f.validation_rms, said{1});
  beyond = str2double(regexp(out, '# validation: (\d+) of its (\d+) inputs', 'tokens', 'once'));
  check(f.excitation.beyond == beyond(1) && f.excitation.holdout_n == beyond(2), ...
        'excitation %d of %d, hyst fit %d of %d', f.excitation.beyond, f.excitation.holdout_n, ...
        beyond(1), beyond(2));
  n = regexp(out, '# validation noise floor: rms (\S+),', 'tokens', 'once');
  if isempty(n)  % the tool says it is not resolved
    check(~isempty(strfind(out, '# validation noise floor: not resolved')) && ...
          isnan(f.excitation.noise), 'validation noise floor %.6g: %s', f.excitation.noise, out);
  else
    check(strcmp(sprintf('%.6g', f.excitation.noise), n{1}), ...
          'validation noise floor %.6g, hyst fit %s', f.excitation.noise, n{1});
  end
  % a degree given: its delay chosen on the validation record
  run_cli(ctx, ['fit --kind everett --degree 2 --validate "' b.file '" --save "' cli_file ...
                '" "' a.file '"']);
  hyst_model_save(oct_file, hyst_fit(a.x, a.y, 'kind', 'everett', 'degree', 2, ...
                                     'validate', [b.x b.y]));
  check(strcmp(fileread(oct_file), fileread(cli_file)), ...
        'hyst_fit(..., ''degree'', 2, ''validate'') differs from hyst fit --degree 2 --validate');
  msg = error_message(@() hyst_fit(a.x, a.y, 'validate', [b.x, 0 * b.y + 2]));
  check(~isempty(strfind(msg, 'Y2 is constant')), 'constant Y2: %s', msg);
  msg = error_message(@() hyst_fit(a.x, a.y, 'validate', b.x));
  check(~isempty(strfind(msg, 'two columns')), 'one column: %s', msg);
end

function t_fit_searches_delays_as_cli(ctx)
  % 'delay', [] searches the delays with the hyst tool's own code
  % (fit_search()): scaled to the drive's period beyond 8 samples, then a
  % fraction of a sample, the model fitted on the drive interpolated
  plant = fullfile(ctx.tmp, 'plant.hyst');
  fid = fopen(plant, 'w');
  fprintf(fid, ['hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0\ndelay 12.5\n' ...
                'degree 2\nterms 3 -0.5 1\n']);
  fclose(fid);
  x = [];
  for top = [40 30 40 20 40 35 40 25 40]
    x = [x, 0:0.05:top - 0.05, top:-0.05:0.05];  %#ok<AGROW>
  end
  x = [x, 0]';
  xf = fullfile(ctx.tmp, 'x.txt');
  fid = fopen(xf, 'w');
  fprintf(fid, '%.17g\n', x);
  fclose(fid);
  y = str2double(strsplit(strtrim(run_cli(ctx, ['sim --model "' plant '" "' xf '"'])), "\n"))';
  rec = fullfile(ctx.tmp, 'rec.txt');
  fid = fopen(rec, 'w');
  fprintf(fid, '%.17g %.17g\n', [x, y]');
  fclose(fid);
  out = run_cli(ctx, ['fit "' rec '"']);
  check(~isempty(regexp(out, '# delays searched 0\.\.\d+ ', 'once')), 'no scaled search: %s', out);
  delay = str2double(regexp(out, '# delay (\S+) samples', 'tokens', 'once'));
  f = hyst_fit(x, y, 'degree', [], 'delay', []);
  check(delay == 12.5 && f.delay == delay, 'delay %g, hyst fit %g', f.delay, delay);
  t = regexp(out, 'chosen by hold-out: degree (\d+), delay \d+ \(kind (\w+)', 'tokens', 'once');
  check(strcmp(f.kind, t{2}) && f.degree == str2double(t{1}), ...
        'the choice differs from hyst fit''s: %s', strjoin(t, ' '));
  % no option: the same choice, saved as the same model file
  cli_file = fullfile(ctx.tmp, 'default_cli.hyst');
  run_cli(ctx, ['fit --save "' cli_file '" "' rec '"']);
  oct_file = fullfile(ctx.tmp, 'default_oct.hyst');
  hyst_model_save(oct_file, hyst_fit(x, y));
  check(strcmp(fileread(oct_file), fileread(cli_file)), 'hyst_fit(x, y) differs from hyst fit');
  % a degree given: its delay chosen as hyst fit --degree 3 chooses it
  out = run_cli(ctx, ['fit --degree 3 "' rec '"']);
  delay = str2double(regexp(out, '# delay (\S+) samples', 'tokens', 'once'));
  g = hyst_fit(x, y, 'degree', 3);
  check(g.delay == delay && delay > 10, 'degree 3: delay %g, hyst fit --degree 3 %g', g.delay, delay);
  check(hyst_fit(x, y, 'degree', 3, 'delay', 0).delay == 0, 'delay 0 given is not kept');
end

% ---- the rate term (hyst/rate.h, docs/rate.md) ----

function write_text(file, text)
  fid = fopen(file, 'w');
  fputs(fid, text);
  fclose(fid);
end

function texts = rate_models()
  % an asymmetric model with a creep lag and a rate term, and f0 on a
  % domain that does not start at 0 with a rate term alone
  texts = {sprintf(['hyst-model-text 1\nkind everett\nlo 0\nhi 40\ny_lo 0.5\ndelay 2\n' ...
                    'degree 3\nterms 3 1 0 2 -0.5 0.4\ncreep_tau 300\ncreep_weight 0.02\n' ...
                    'rate_tau 4\nrate_weight 0.3\n']), ...
           sprintf(['hyst-model-text 1\nkind poly\nlo 5\nhi 40\n' ...
                    'coeffs -6.1876e-6 1.1949e-3 8.6444e-2 5.8517e-1\n' ...
                    'rate_tau 1\nrate_weight -0.05\n'])};
end

function t_rate_sim_inv_equal_cli(ctx)
  % a model file with a rate term runs bit for bit as hyst sim --model and
  % its compensator as hyst inv --model; the term is there: the model
  % without it differs by the low-pass of the clamped input's change
  file = fullfile(ctx.tmp, 'rate.hyst');
  texts = rate_models();
  for k = 1:numel(texts)
    write_text(file, texts{k});
    m = hyst_model_load(file);
    check(isfield(m, 'rate_tau') && isfield(m, 'rate_weight'), 'model %d: no rate fields', k);
    x = signal(3000, m.lo, m.hi, 40 + k);
    y = hyst_sim(m, x);
    check(cli_model_equal(ctx, 'sim', file, x, y, m.delay), ...
          'model %d: sim differs from hyst sim --model', k);
    u = min(max(x, m.lo), m.hi);
    v = 0;
    last = m.lo;
    r = zeros(size(u));
    for i = 1:numel(u)  % the rate term by its definition
      r(i) = m.rate_weight * v;
      v = v + ((u(i) - last) - v) / m.rate_tau;
      last = u(i);
    end
    diff = y - hyst_sim(rmfield(m, {'rate_tau', 'rate_weight'}), x);
    check(max(abs(diff)) > 0.1 && max(abs(diff - r)) < 1e-12, ...
          'model %d: not the rate term of its definition', k);
    xd = hyst_inv(m, y);
    check(cli_model_equal(ctx, 'inv', file, y, xd, 0), 'model %d: inv differs from hyst inv --model', k);
    check(max(abs(xd - u)) < 1e-9 * (m.hi - m.lo), 'model %d: inv(sim(x)) is not x', k);
  end
end

function t_rate_written_as_cli(ctx)
  % hyst_model_save writes a loaded rate term back as the tool writes it
  % (the same model loaded again); hyst_header's rate block is 'hyst header
  % --model''s; refused: a rate field alone, not a scalar, tau below 1
  file = fullfile(ctx.tmp, 'rate.hyst');
  again = fullfile(ctx.tmp, 'rate_again.hyst');
  texts = rate_models();
  for k = 1:numel(texts)
    write_text(file, texts{k});
    m = hyst_model_load(file);
    hyst_model_save(again, m);
    check(isequal(hyst_model_load(again), m), 'model %d: not the same model back', k);
    t = fileread(again);
    check(~isempty(strfind(t, sprintf('rate_tau %.17g\nrate_weight %.17g', m.rate_tau, ...
                                      m.rate_weight))), 'model %d: no rate keys', k);
    run_cli(ctx, sprintf('header --model "%s" --dir "%s" mdl', file, ctx.tmp));
    cli = fileread(fullfile(ctx.tmp, 'mdl.h'));
    h = hyst_header(m, 'mdl');
    first = strfind(h, '/* rate:');
    last = strfind(h, 'mdl_rate_weight =');
    stop = strfind(h(last:end), ';');
    block = h(first:last + stop(1) - 1);
    check(~isempty(first) && ~isempty(strfind(cli, block)) && ...
          ~isempty(strfind(h, '#include "hyst/rate.h"')), ...
          'model %d: the header''s rate block is not hyst header''s', k);
  end
  m.rate_tau = 0.5;
  expect_error('hyst:usage', @() hyst_model_save(again, m));
end

function t_rate_refused(ctx)
  % a rate field alone or not a scalar is refused, and a time constant the
  % library refuses; nothing written
  file = fullfile(ctx.tmp, 'rate.hyst');
  texts = rate_models();
  write_text(file, texts{2});
  m = hyst_model_load(file);
  expect_error('hyst:usage', @() hyst_model_save(fullfile(ctx.tmp, 'rate_bad.hyst'), ...
                                                 rmfield(m, 'rate_tau')));
  check(~exist(fullfile(ctx.tmp, 'rate_bad.hyst'), 'file'), 'a file was written');
  expect_error('hyst:usage', @() hyst_sim(rmfield(m, 'rate_weight'), 1));
  m.rate_tau = [1 2];
  expect_error('hyst:usage', @() hyst_sim(m, 1));
  expect_error('hyst:usage', @() hyst_header(m, 'rate_model'));
  m.rate_tau = 0.5;  % below 1 sample: the library refuses it
  expect_error('hyst:ERR_ARG', @() hyst_sim(m, 1));
end

function t_rate_fit_as_cli(ctx)
  % hyst_fit(x, y, 'rate', R) scores and fits the rate term as hyst fit
  % --rate R: the same model file; 'rate' with a degree given is refused
  file = fullfile(ctx.tmp, 'rate_plant.hyst');
  texts = rate_models();
  write_text(file, texts{1});
  x = signal(3000, 0, 40, 5);
  y = hyst_sim(hyst_model_load(file), x);
  rec = fullfile(ctx.tmp, 'rate_rec.txt');
  fid = fopen(rec, 'w');
  fprintf(fid, '%.17g %.17g\n', [x, y]');
  fclose(fid);
  cases = {1, '1'; 'auto', 'auto'};
  for k = 1:size(cases, 1)
    cli_file = fullfile(ctx.tmp, 'rate_cli.hyst');
    run_cli(ctx, sprintf('fit --rate %s --save "%s" "%s" 2>&1', cases{k, 2}, cli_file, rec));
    oct_file = fullfile(ctx.tmp, 'rate_oct.hyst');
    f = hyst_fit(x, y, 'rate', cases{k, 1});
    hyst_model_save(oct_file, f);
    check(strcmp(fileread(oct_file), fileread(cli_file)), ...
          'rate %s: hyst_fit differs from hyst fit --rate', cases{k, 2});
    check(k > 1 || (isfield(f, 'rate_tau') && f.rate_tau == 1), 'rate 1: no rate term');
  end
  expect_error('hyst:usage', @() hyst_fit(x, y, 'degree', 3, 'rate', 1));
  expect_error('hyst:usage', @() hyst_fit(x, y, 'rate', 0.5));
end

% ---- the asymmetric kind on a grid (model files of kind everett_grid) ----

function text = grid_plant_text(with_creep)
  % tests/cli/grid.sh's plant: a near step between 1 and 1.4 of 0..3; with
  % a delay, an identified range and a creep term too
  text = sprintf(['hyst-model-text 1\nkind everett_grid\nlo 0\nhi 3\ny_lo 0\n' ...
                  'knots 0 1 1.4 3\nweights 1 0.5 8 0.2 0.5 1\n']);
  if with_creep
    text = [text sprintf('delay 2\nidentified 0.5 2.5\ncreep_tau 300\ncreep_weight 0.05\n')];
  end
end

function x = grid_loops()
  % tests/cli/grid.sh's record's input: minor loops of decreasing size
  x = [];
  for c = 0:11
    a = 3 - c * 0.2;
    b = c * 0.2;
    x = [x, b:0.01:a - 1e-9, a:-0.01:b + 1e-9];  %#ok<AGROW>
  end
  x = x(:);
end

function t_grid_sim_inv_equal_cli(ctx)
  % a model file of kind everett_grid runs bit for bit as hyst sim --model
  % (output delay samples later) and its compensator as hyst inv --model;
  % the model driven by the compensator gives the desired outputs back
  file = fullfile(ctx.tmp, 'grid.hyst');
  for with_creep = [false true]
    write_text(file, grid_plant_text(with_creep));
    m = hyst_model_load(file);
    check(strcmp(m.kind, 'everett_grid') && isequal(m.knots, [0 1 1.4 3]) && ...
          isequal(m.weights, [1 0.5 8 0.2 0.5 1]) && m.y_lo == 0, 'the grid as loaded');
    x = [signal(3000, 0, 3, 40); grid_loops()];
    y = hyst_sim(m, x);
    check(cli_model_equal(ctx, 'sim', file, x, y, m.delay), ...
          'creep %d: sim differs from hyst sim --model', with_creep);
    xd = hyst_inv(m, y);
    check(cli_model_equal(ctx, 'inv', file, y, xd, 0), 'creep %d: inv differs from hyst inv --model', ...
          with_creep);
    err = max(abs(hyst_sim(m, xd) - y));
    check(err < 1e-8 * (max(y) - min(y)), 'creep %d: |sim(inv(y)) - y| up to %g', with_creep, err);
    ys = hyst_sim(m, single(x));
    check(isa(ys, 'single') && max(abs(double(ys) - y)) < 1e-5 * (max(y) - min(y)), ...
          'creep %d: single does not follow double', with_creep);
  end
end

function t_grid_written_as_cli(ctx)
  % a grid fitted and saved by hyst fit --kind everett_grid, loaded and
  % saved again: the same text; the creep plant's file round-trips
  [~, ~, rec] = grid_record(ctx);
  cli_file = fullfile(ctx.tmp, 'grid_cli.hyst');
  run_cli(ctx, sprintf(['fit --kind everett_grid --degree 3 --delay 0 --creep none ' ...
                        '--save "%s" "%s" 2>&1'], cli_file, rec));
  plant = fullfile(ctx.tmp, 'grid_plant.hyst');
  again = fullfile(ctx.tmp, 'grid_again.hyst');
  hyst_model_save(again, hyst_model_load(cli_file));
  check(strcmp(fileread(again), fileread(cli_file)), 'the text differs from hyst fit --save''s');
  write_text(plant, grid_plant_text(true));
  hyst_model_save(again, hyst_model_load(plant));
  check(isequal(hyst_model_load(again), hyst_model_load(plant)), 'the creep plant differs');
end

function t_grid_header_equals_cli(ctx)
  % hyst_header of a grid: hyst header --model's text after the first line
  file = fullfile(ctx.tmp, 'grid_h.hyst');
  write_text(file, grid_plant_text(false));
  run_cli(ctx, sprintf('header --model "%s" --dir "%s" gridm 2>&1', file, ctx.tmp));
  cli_text = fileread(fullfile(ctx.tmp, 'gridm.h'));
  text = hyst_header(hyst_model_load(file), 'gridm');
  check(strcmp(after_first_line(text), after_first_line(cli_text)), ...
        'hyst_header differs from hyst header --model');
  % the compensator: the same text as hyst header --compensator, no table
  run_cli(ctx, sprintf('header --model "%s" --dir "%s" --compensator gridm 2>&1', file, ctx.tmp));
  cli_text = fileread(fullfile(ctx.tmp, 'gridm.h'));
  text = hyst_header(hyst_model_load(file), 'gridm', 'compensator', true);
  check(~isempty(strfind(text, 'hyst_curve_everett_grid_inverse()')) && ...
        strcmp(after_first_line(text), after_first_line(cli_text)), ...
        'hyst_header ''compensator'' differs from hyst header --compensator');
end

function t_grid_refused(ctx)
  m = hyst_model_load(fullfile(ctx.tmp, 'grid_h.hyst'));
  expect_error('hyst:usage', @() hyst_inv(m, 1, 'intervals', 32));
  expect_error('hyst:usage', @() hyst_header(m, 'g', 'compensator', true, 'intervals', 32));
  bad = m;
  bad.weights(2) = -0.5;
  expect_error('hyst:ERR_NOT_MONOTONE', @() hyst_sim(bad, 1));
  bad = m;
  bad.weights = [1 2];
  expect_error('hyst:usage', @() hyst_model_save(fullfile(ctx.tmp, 'bad.hyst'), bad));
  check(~exist(fullfile(ctx.tmp, 'bad.hyst'), 'file'), 'a refused model was written');
end

function [x, y, rec] = grid_record(ctx)
  x = grid_loops();
  plant = fullfile(ctx.tmp, 'grid_plant.hyst');
  write_text(plant, grid_plant_text(false));
  y = hyst_sim(hyst_model_load(plant), x);
  rec = fullfile(ctx.tmp, 'grid_rec.txt');
  fid = fopen(rec, 'w');
  fprintf(fid, '%.17g %.17g\n', [x y]');
  fclose(fid);
end

function t_grid_fit_as_cli(ctx)
  % 'kind', 'everett_grid' fits as hyst fit --kind everett_grid: the same
  % knots and masses, the knots near the plant's
  [x, y, rec] = grid_record(ctx);
  cli_file = fullfile(ctx.tmp, 'grid_cli.hyst');
  run_cli(ctx, sprintf(['fit --kind everett_grid --degree 3 --delay 0 --creep none ' ...
                        '--save "%s" "%s" 2>&1'], cli_file, rec));
  c = hyst_model_load(cli_file);
  f = hyst_fit(x, y, 'kind', 'everett_grid', 'degree', 3, 'delay', 0, 'creep', 'none');
  check(strcmp(f.kind, 'everett_grid') && f.monotone && isequal(f.knots, c.knots) && ...
        isequal(f.weights, c.weights) && f.y_lo == c.y_lo, 'the grid differs from hyst fit''s');
  check(abs(f.knots(2) - 1) < 0.02 && abs(f.knots(3) - 1.4) < 0.02, 'knots %s', mat2str(f.knots));
  err = sqrt(mean((hyst_sim(f, x) - y) .^ 2));
  check(err < 0.01 * (max(y) - min(y)), 'the fitted grid misses the plant by %g', err);
end

function t_grid_fit_undetermined(ctx)
  % major loops determine every mass of 3 intervals, not how the inner cells
  % of 4 share theirs: determined false and a warning hyst:undetermined in
  % hyst fit's words, which warns too
  x = repmat([0:0.01:2.99, 3:-0.01:0.01], 1, 3);
  plant = fullfile(ctx.tmp, 'grid_plant_u.hyst');
  write_text(plant, grid_plant_text(false));
  y = hyst_sim(hyst_model_load(plant), x);
  rec = fullfile(ctx.tmp, 'grid_major.txt');
  write_text(rec, sprintf('%.17g %.17g\n', [x; y]));
  lastwarn('');
  f3 = hyst_fit(x, y, 'kind', 'everett_grid', 'degree', 3, 'delay', 0, 'creep', 'none');
  [~, id] = lastwarn();
  check(f3.determined && ~strcmp(id, 'hyst:undetermined'), '3 intervals said undetermined');
  f4 = hyst_fit(x, y, 'kind', 'everett_grid', 'degree', 4, 'delay', 0, 'creep', 'none');
  [msg, id] = lastwarn();
  check(~f4.determined && strcmp(id, 'hyst:undetermined') && ~isfield(f4, 'undetermined_why'), ...
        '4 intervals on major loops: %s %s', id, msg);
  out = run_cli(ctx, sprintf(['fit --kind everett_grid --degree 4 --delay 0 --creep none ' ...
                              '"%s" 2>&1'], rec));
  check(~isempty(strfind(out, strrep(msg, 'hyst_fit: ', ''))), 'hyst fit says otherwise: %s', out);
end

function t_grid_chosen_as_cli(ctx)
  % 'degree', [] considers the grids as hyst fit does: on the near step (a
  % sharp loop, as an SMA's) both choose a grid, of the same degree and
  % delay, and save the same model
  [x, y, rec] = grid_record(ctx);
  cli_file = fullfile(ctx.tmp, 'grid_auto.hyst');
  out = run_cli(ctx, sprintf('fit --creep none --save "%s" "%s" 2>&1', cli_file, rec));
  t = regexp(out, 'chosen by hold-out: degree (\d+), delay (\d+) \(kind (\w+)', 'tokens', 'once');
  f = hyst_fit(x, y, 'degree', [], 'delay', [], 'creep', 'none');
  check(strcmp(t{3}, 'everett_grid') && strcmp(f.kind, 'everett_grid') && ...
        f.degree == str2double(t{1}) && f.delay == str2double(t{2}), ...
        'the choice differs from hyst fit''s: %s', strjoin(t, ' '));
  kinds = unique({f.candidates.kind});
  check(isequal(kinds, {'everett', 'everett_grid', 'poly', 'spline'}), 'kinds %s', ...
        strjoin(kinds, ' '));
  c = hyst_model_load(cli_file);
  check(isequal(f.knots, c.knots) && isequal(f.weights, c.weights), 'the grid saved differs');
end

% ---- the symmetric kind whose f0 is a cubic spline (model files of kind spline) ----

function s = spline_cubic()
  % f0 = x^3 + x on [0, 1] in two pieces: a cubic is its own Hermite spline
  s = struct('kind', 'spline', 'lo', 0, 'hi', 1, 'values', [0 0.625 2], 'slopes', [1 1.75 4]);
end

function text = spline_cubic_text(with_terms)
  % spline_cubic()'s model file (tests/cli/spline.sh's one.hyst); with a
  % delay, an identified range, a creep and a rate term too
  text = sprintf('hyst-model-text 1\nkind spline\nlo 0\nhi 1\nvalues 0 0.625 2\nslopes 1 1.75 4\n');
  if with_terms
    text = [text sprintf(['delay 2\nidentified 0.25 0.75\ncreep_tau 300\ncreep_weight 0.05\n' ...
                          'rate_tau 4\nrate_weight 0.1\n'])];
  end
end

function t_spline_runs_as_its_polynomial(ctx)
  % the spline of f0 = x^3 + x runs as the polynomial model within
  % rounding, in double and single, exactly at tests/cli/spline.sh's
  % inputs; its file runs bit for bit as hyst sim --model (output delay
  % samples later), with its creep and rate terms too
  s = spline_cubic();
  p = struct('coeffs', [1 0 1 0], 'lo', 0, 'hi', 1);
  y = hyst_sim(s, [0 0.25 0.5 1 0.5 0.75 0]);
  check(isequal(y, [0 0.265625 0.625 2 1.375 1.640625 0]), 'at the knots'' inputs: %s', ...
        mat2str(y));
  x = signal(3000, 0, 1, 41);
  [ys, st] = hyst_sim(s, x);  % x has samples outside [0, 1]: clamped, status 1
  err = max(abs(ys - hyst_sim(p, x)));
  check(st == 1 && err < 1e-12, 'double: %g from f0''s (status %d)', err, st);
  ys1 = hyst_sim(s, single(x));
  check(isa(ys1, 'single') && isequal(size(ys1), size(x)) && ...
        max(abs(double(ys1) - double(hyst_sim(p, single(x))))) < 4e-6, ...
        'single: the spline is not the polynomial');
  file = fullfile(ctx.tmp, 'spline.hyst');
  for with_terms = [false true]
    write_text(file, spline_cubic_text(with_terms));
    m = hyst_model_load(file);
    y = hyst_sim(m, x);
    check(cli_model_equal(ctx, 'sim', file, x, y, m.delay), ...
          'terms %d: sim differs from hyst sim --model', with_terms);
    check(with_terms == (max(abs(y - ys)) > 1e-3), 'terms %d: the terms are not run', with_terms);
  end
end

function t_spline_inv_undoes_sim(ctx)
  % the compensator (hyst_curve_spline_inverse()) gives the drives of the
  % model's outputs back, as the polynomial's exact inverse does, bit for
  % bit hyst inv --model's (with the creep and rate terms too); a desired
  % output outside [f0(lo), f0(hi)] is clamped; a flat piece has no inverse
  s = spline_cubic();
  x = signal(3000, 0, 1, 42);
  u = min(max(x, 0), 1);
  y = hyst_sim(s, x);
  [xi, st, ~, inv_err] = hyst_inv(s, y);
  check(st == 0 && inv_err == 0 && max(abs(xi - u)) < 1e-12, 'double: inv(sim(x)) is x within %g', ...
        max(abs(xi - u)));
  check(max(abs(xi - hyst_inv(struct('coeffs', [1 0 1 0], 'lo', 0, 'hi', 1), y))) < 1e-12, ...
        'not the polynomial''s compensator');
  xs = hyst_inv(s, single(y));
  check(isa(xs, 'single') && max(abs(double(xs) - u)) < 1e-5, 'single: inv(sim(x)) is not x');
  [xc, st] = hyst_inv(s, [-1; 3]);
  check(st == 1 && isequal(xc, [0; 1]), 'outside [f0(lo), f0(hi)]: %s, status %d', mat2str(xc), st);
  file = fullfile(ctx.tmp, 'spline.hyst');
  for with_terms = [false true]
    write_text(file, spline_cubic_text(with_terms));
    m = hyst_model_load(file);
    yd = hyst_sim(m, x);
    xd = hyst_inv(m, yd);
    check(cli_model_equal(ctx, 'inv', file, yd, xd, 0), ...
          'terms %d: inv differs from hyst inv --model', with_terms);
    check(max(abs(xd - u)) < 1e-9, 'terms %d: inv(sim(x)) is not x', with_terms);
  end
  flat = struct('kind', 'spline', 'lo', 0, 'hi', 2, 'values', [0 0 1], 'slopes', [0 0 2]);
  hyst_sim(flat, [0 1 2]);  % runs: f0 may be flat, its inverse not
  expect_error('hyst:ERR_NOT_INVERTIBLE', @() hyst_inv(flat, 0.5));
end

function t_spline_inv_table_equals_cli(ctx)
  % hyst_inv(s, y, 'intervals', N): the tabulated compensator
  % (hyst_*_curve_spline_inverse_table()), bit for bit hyst inv --model
  % --intervals N (with a creep term too), INV_ERR the error it prints, not
  % the solved compensator's drives; single: hyst_f32_*; with
  % 'compensator', true, 'intervals', N hyst_header is hyst header
  % --compensator --intervals N
  [plant, x] = spline_plant();
  file = fullfile(ctx.tmp, 'spline_plant.hyst');
  hyst_model_save(file, plant);
  y = hyst_sim(plant, x);
  exact = hyst_inv(plant, y);
  fin = fullfile(ctx.tmp, 'spline_tab_in.txt');
  write_numbers(fin, y);
  for n = [8 64 256]
    [xt, st, ~, err] = hyst_inv(plant, y, 'intervals', n);
    check(st == 0 && err > 0 && max(abs(xt - exact)) > 0, ...
          'intervals %d: status %d, error %g: the table was not used', n, st, err);
    check(cli_model_equal(ctx, sprintf('inv --intervals %d', n), file, y, xt, 0), ...
          'intervals %d: differs from hyst inv --model --intervals', n);
    said = run_cli(ctx, sprintf('inv --model "%s" --intervals %d "%s" 2>&1 >/dev/null', ...
                                file, n, fin));
    cli_err = sscanf(said(strfind(said, 'measured error') + numel('measured error'):end), '%g', 1);
    check(abs(err - cli_err) <= 1e-8 * cli_err, 'intervals %d: error %.9g, hyst inv: %s', n, ...
          err, said);
  end
  xs = hyst_inv(plant, single(y), 'intervals', 64);
  check(isa(xs, 'single') && max(abs(double(xs) - exact)) < 1e-4, 'single: %g from the solved', ...
        max(abs(double(xs) - exact)));
  hyst_model_save(file, setfield(setfield(plant, 'creep_tau', 300), 'creep_weight', 0.05));
  m = hyst_model_load(file);
  ym = hyst_sim(m, x);
  check(cli_model_equal(ctx, 'inv --intervals 64', file, ym, hyst_inv(m, ym, 'intervals', 64), 0), ...
        'creep: differs from hyst inv --model --intervals');
  run_cli(ctx, sprintf('header --model "%s" --dir "%s" --compensator --intervals 64 spc 2>&1', ...
                       file, ctx.tmp));
  text = hyst_header(m, 'spc', 'compensator', true, 'intervals', 64);
  check(~isempty(strfind(text, 'spline_inverse_table(&comp, &fwd, comp_table, spc_INTERVALS)')) && ...
        strcmp(after_first_line(text), after_first_line(fileread(fullfile(ctx.tmp, 'spc.h')))), ...
        'intervals 64: hyst_header differs from hyst header --compensator --intervals');
end

function t_spline_save_load(ctx)
  % a spline struct saved and loaded: the same struct, the file the
  % format's text (every key the tool writes); its file with every term
  % round-trips
  s = spline_cubic();
  file = fullfile(ctx.tmp, 'spline_saved.hyst');
  hyst_model_save(file, s);
  m = hyst_model_load(file);
  check(isequal(m, setfield(s, 'delay', 0)), 'not the same model back');
  t = fileread(file);
  check(~isempty(strfind(t, sprintf(['\nkind spline\nlo 0\nhi 1\ndelay 0\nvalues 0 0.625 2\n' ...
                                     'slopes 1 1.75 4\n']))), 'the text: %s', t);
  plant = fullfile(ctx.tmp, 'spline_terms.hyst');
  write_text(plant, spline_cubic_text(true));
  m = hyst_model_load(plant);
  check(m.delay == 2 && isequal(m.identified, [0.25 0.75]) && m.creep_tau == 300 && ...
        m.rate_weight == 0.1, 'the terms as loaded');
  hyst_model_save(file, m);
  check(isequal(hyst_model_load(file), m), 'the model with its terms differs once saved');
  s.values = s.values + pi;  % 17 digits: the same doubles back
  s.slopes = s.slopes / 3;
  hyst_model_save(file, s);
  m = hyst_model_load(file);
  check(isequal(m.values, s.values) && isequal(m.slopes, s.slopes), 'not the same doubles back');
end

function t_spline_header_equals_cli(ctx)
  % hyst_header of a spline: hyst header --model's text after the first
  % line, with its terms, and with 'compensator' (no table) hyst header
  % --compensator's
  file = fullfile(ctx.tmp, 'spline_h.hyst');
  for with_terms = [false true]
    write_text(file, spline_cubic_text(with_terms));
    m = hyst_model_load(file);
    run_cli(ctx, sprintf('header --model "%s" --dir "%s" splm 2>&1', file, ctx.tmp));
    text = hyst_header(m, 'splm');
    check(~isempty(strfind(text, 'static const hyst_spline_t splm')) && ...
          strcmp(after_first_line(text), after_first_line(fileread(fullfile(ctx.tmp, 'splm.h')))), ...
          'terms %d: hyst_header differs from hyst header --model', with_terms);
    run_cli(ctx, sprintf('header --model "%s" --dir "%s" --compensator splm 2>&1', file, ctx.tmp));
    text = hyst_header(m, 'splm', 'compensator', true);
    check(~isempty(strfind(text, 'hyst_curve_spline_inverse()')) && ...
          strcmp(after_first_line(text), after_first_line(fileread(fullfile(ctx.tmp, 'splm.h')))), ...
          'terms %d: ''compensator'' differs from hyst header --compensator', with_terms);
  end
end

function t_spline_refused(ctx)
  % what the tool refuses of a spline is refused here: rows for its
  % tabulated compensator (hyst inv --rows, hyst header --rows), intervals
  % out of range, a flat piece (no compensator, tabulated or not), a piece
  % that falls (the library), counts and slopes the model file's reader
  % refuses (nothing written), a spline file the reader refuses (in its
  % words)
  s = spline_cubic();
  expect_error('hyst:usage', @() hyst_inv(s, 1, 'rows', 8));
  expect_error('hyst:usage', @() hyst_inv(s, 1, 'intervals', 32, 'rows', 8));
  expect_error('hyst:usage', @() hyst_inv(s, 1, 'intervals', 0.5));
  expect_error('hyst:usage', @() hyst_inv(s, 1, 'intervals', 2^20 + 1));
  expect_error('hyst:usage', @() hyst_header(s, 'sp', 'compensator', true, 'rows', 8));
  flat = struct('kind', 'spline', 'lo', 0, 'hi', 2, 'values', [0 0 1], 'slopes', [0 0 2]);
  expect_error('hyst:ERR_NOT_INVERTIBLE', @() hyst_inv(flat, 0.5, 'intervals', 32));
  falls = s;
  falls.values = [0 1.9 2];  % the reader takes it, the library refuses it
  expect_error('hyst:ERR_NOT_INCREASING', @() hyst_sim(falls, 0.5));
  expect_error('hyst:ERR_NOT_INCREASING', @() hyst_inv(falls, 0.5));
  expect_error('hyst:ERR_NOT_INCREASING', @() hyst_header(falls, 'sp'));
  bad = {setfield(s, 'slopes', [1 -1.75 4]), setfield(s, 'slopes', [1 1.75]), ...
         setfield(s, 'values', 1), setfield(s, 'values', 0:33), setfield(s, 'values', [0 NaN 2]), ...
         rmfield(s, 'slopes')};
  file = fullfile(ctx.tmp, 'spline_bad.hyst');
  for k = 1:numel(bad)
    expect_error('hyst:usage', @() hyst_model_save(file, bad{k}));
    expect_error('hyst:usage', @() hyst_header(bad{k}, 'sp'));
    check(~exist(file, 'file'), 'refused model %d was written', k);
  end
  expect_error('hyst:usage', @() hyst_sim(setfield(s, 'slopes', [1 1.75]), 0.5));
  write_text(file, strrep(spline_cubic_text(false), 'slopes 1 1.75 4', 'slopes 1 -1.75 4'));
  msg = error_message(@() hyst_model_load(file));
  [~, said] = system(sprintf('"%s" sim --model "%s" < /dev/null 2>&1', ctx.cli, file));
  check(~isempty(strfind(msg, ':6: field 3: ''-1.75'' is not a slope >= 0 (f0 increases)')) && ...
        ~isempty(strfind(said, msg(numel('hyst_model_load: ') + 1:end))), ...
        'the reader''s words: %s; hyst sim: %s', msg, said);
end

function [plant, x] = spline_plant()
  % tests/cli/spline.sh's plant: f0 a C2 spline of 5 intervals on [0, 3] (a
  % near step), written from its I-spline weights (the fit's own class),
  % and its drive: minor loops of decreasing size, then a major loop
  w = [0.3 0.2 0.2 2.5 2.5 0.2 0.1];
  K = 5;
  values = 0.5 + [0 cumsum(w(1:K) + 4 * w(2:K + 1) + w(3:K + 2)) / 6];
  slopes = (w(1:K + 1) + w(2:K + 2)) / 2 * K / 3;
  plant = struct('kind', 'spline', 'lo', 0, 'hi', 3, 'values', values, 'slopes', slopes);
  x = [grid_loops(); (0:0.01:2.995)'; (3:-0.01:-0.005)'];
  x = round(x * 100) / 100;
end

function t_spline_fit_recovers_the_plant(ctx)
  % 'kind', 'spline' recovers a spline of its class from a record with minor
  % loops (where f0 of a degree is biased); on the plant's noisy output, 2
  % samples late, it chooses as hyst fit --kind spline does (5 intervals,
  % delay 2) and writes its model file byte for byte, as it does with a
  % degree, a creep term, a wider domain (f0 continued: identified saved)
  % and a rate term; without 'kind' the spline is compared with the others
  [plant, x] = spline_plant();
  y = hyst_sim(plant, x);
  f = hyst_fit(x, y, 'kind', 'spline', 'degree', 5, 'delay', 0, 'creep', 'none');
  check(strcmp(f.kind, 'spline') && f.increasing && f.degree == 5 && f.intervals == 5 && ...
        max(abs(f.values - plant.values)) < 1e-9 && max(abs(f.slopes - plant.slopes)) < 1e-9, ...
        'not the plant: values %s, slopes %s', mat2str(f.values, 6), mat2str(f.slopes, 6));
  rand('state', 7);
  yd = [y(1); y(1); y(1:end - 2)] + (rand(size(y)) - 0.5) * 0.01;  % +-0.005 of noise
  rec = fullfile(ctx.tmp, 'spline_rec.txt');
  fid = fopen(rec, 'w');
  fprintf(fid, '%.17g %.17g\n', [x yd]');
  fclose(fid);
  cases = {'', {};
           '--degree 5', {'degree', 5};
           '--degree 5 --delay 2 --creep 500 --domain -1,4', ...
           {'degree', 5, 'delay', 2, 'creep', 500, 'domain', [-1 4]};
           '--creep none --rate 1', {'creep', 'none', 'rate', 1}};
  cli_file = fullfile(ctx.tmp, 'spline_cli.hyst');
  oct_file = fullfile(ctx.tmp, 'spline_oct.hyst');
  for k = 1:size(cases, 1)
    out = run_cli(ctx, sprintf('fit --kind spline %s --save "%s" "%s" 2>&1', cases{k, 1}, ...
                               cli_file, rec));
    f = hyst_fit(x, yd, 'kind', 'spline', cases{k, 2}{:});
    hyst_model_save(oct_file, f);
    check(strcmp(fileread(oct_file), fileread(cli_file)), ...
          '%s: hyst_fit differs from hyst fit --kind spline:\n%s\n%s', cases{k, 1}, ...
          fileread(oct_file), fileread(cli_file));
    if k == 1  % the plant's class: 5 intervals, its delay, its output within the noise
      t = regexp(out, 'chosen by hold-out: degree (\d+), delay (\d+) \(kind spline', 'tokens', 'once');
      check(~isempty(t) && f.degree == 5 && str2double(t{1}) == 5 && f.delay == 2 && ...
            str2double(t{2}) == 2 && isequal(unique({f.candidates.kind}), {'spline'}) && ...
            numel(f.candidates) >= 15, 'the choice: %s', out);
      err = sqrt(mean((hyst_sim(f, x) - y) .^ 2));  % hyst_sim: the model, without the delay
      check(err < 0.001, 'the fitted spline misses the plant by %g', err);
    elseif k == 3  % 5 intervals fitted, more to cover the domain beyond the inputs [0, 3]
      check(f.degree == 5 && f.intervals > 5 && f.lo <= -1 && f.hi >= 4 && ...
            isequal(f.identified, [0 3]) && f.creep_tau == 500, ...
            'the domain''s continuation: %d intervals on [%g, %g]', f.intervals, f.lo, f.hi);
      % run as hyst sim --model runs it, below the inputs too (the creep at rest at lo)
      xs = [x; -1; -0.5; 1];
      check(cli_model_equal(ctx, 'sim', cli_file, xs, hyst_sim(f, xs), 2), ...
            'the continued model differs from hyst sim''s');
    elseif k == 4
      check(f.rate_tau == 1 && ~isfield(f, 'creep_tau'), 'no rate term alone');
    end
  end
  a = hyst_fit(x, yd, 'creep', 'none');
  check(any(strcmp({a.candidates.kind}, 'spline')) && any(strcmp({a.candidates.kind}, 'poly')), ...
        'the default choice did not compare the spline with the others');
  expect_error('hyst:usage', @() hyst_fit(x, yd, 'kind', 'spline', 'degree', 33));
  expect_error('hyst:usage', @() hyst_fit(x, yd, 'kind', 'spline', 'degree', 3, 'tdegree', 1));
  expect_error('hyst:usage', @() hyst_fit(x, yd, 'kind', 'spline', 'method', 'branches'));
end

function x = edge_drive()
  % triangles 0..10, 900 samples
  x = 10 * abs(mod((0:899)' + 50, 100) - 50) / 50;
end

function t_fit_checks_record_as_cli(ctx)
  % hyst_fit refuses a record as hyst fit does, by the tool's own check
  % (fit_record_check()): a response whose correlation with the drive is
  % just below -1/2 is refused by both, just above by neither; a missing
  % (NaN) sample counts as the row left out of the tool's file
  file = fullfile(ctx.tmp, 'edge.txt');
  x = edge_drive();
  xc = x - mean(x);
  z = cos(0.37 * (0:899)');
  z = z - mean(z);
  z = z - (z' * xc) / (xc' * xc) * xc;
  z = z * norm(xc) / norm(z);
  warning('off', 'hyst:not_increasing', 'local');
  for side = [-1 1]
    r = -0.5 + side * 1e-6;
    y = 5 - xc + sqrt(1 / r ^ 2 - 1) * z;
    c = corrcoef(x, y);
    check(abs(c(1, 2) - r) < 1e-7, 'correlation %.9g, not %.9g', c(1, 2), r);
    fid = fopen(file, 'w');
    fprintf(fid, '%.17g %.17g\n', [x y]');
    fclose(fid);
    [rc, out] = system(sprintf('"%s" fit --degree 1 --delay 0 --creep none "%s" 2>&1', ...
                               ctx.cli, file));
    cli_refused = rc == 1 && ~isempty(strfind(out, 'falls as the input (column 1) rises'));
    % the record, and the same with a missing drive, response and both inserted
    recs = {{x, y}, {[x(1:5); NaN; x(6:300); 6; x(301:600); NaN; x(601:end)], ...
                     [y(1:5); 4; y(6:300); NaN; y(301:600); NaN; y(601:end)]}};
    for k = 1:2
      msg = '';
      try
        hyst_fit(recs{k}{:}, 'degree', 1, 'delay', 0, 'creep', 'none');
      catch err
        msg = err.message;
      end
      refused = ~isempty(strfind(msg, 'y falls as x rises'));
      check(refused == cli_refused && refused == (side < 0), ...
            'correlation -1/2 %+d e-6 (record %d): hyst_fit "%s", hyst fit (%d) "%s"', side, k, ...
            msg, rc, out);
    end
  end
end

function x = loops_drive(minor)
  % triangles 0..10, 0.1 a sample; with minor the later ones turn at 7 and
  % 3 (three reversals inside the range each)
  up = linspace(0, 10, 101)';
  down = linspace(10, 0, 101)';
  down = down(2:end);
  a = linspace(0, 7, 71)';
  b = linspace(7, 3, 41)';
  c = linspace(3, 7, 41)';
  d = linspace(7, 0, 71)';
  inner = [a; b(2:end); c(2:end); d(2:end)];
  later = [up(2:end); down];
  if minor
    later = inner;
  end
  x = [up; down; up; down; up; down; later; later; later];
end

function t_fit_recovers_a_simulated_plant(~)
  % a record the model computed, without noise: errors below the record's
  % resolution count as it, so the plant's degree 3 and delay 3 win, with
  % no creep term, not the candidate whose rounding is 1 % lower
  f0 = paper_f0();
  x = repmat([0:0.25:39.75, 40:-0.25:0.25]', 9, 1);
  y = hyst_sim(f0, x);
  x = x(4:end);
  y = y(1:end - 3);
  s = warning('off', 'hyst:excitation');
  f = hyst_fit(x, y, 'degree', [], 'delay', []);
  warning(s);
  kind = 'poly';
  if isfield(f, 'kind')
    kind = f.kind;
  end
  check(strcmp(kind, 'poly') && f.degree == 3 && f.delay == 3 && ~isfield(f, 'creep_tau'), ...
        'kind %s degree %d delay %g', kind, f.degree, f.delay);
end

function t_fit_warns_degree_on_minor_loops(ctx)
  % f0 of a given degree on a drive with minor loops is biased: hyst_fit
  % warns as hyst fit does (hyst:minor_loops), on major loops only neither
  % does, nor for the asymmetric kind
  file = fullfile(ctx.tmp, 'loops.txt');
  for minor = [false true]
    x = loops_drive(minor);
    y = hyst_sim(struct('coeffs', [0.05 1 0], 'lo', 0, 'hi', 10), x);
    fid = fopen(file, 'w');
    fprintf(fid, '%.17g %.17g\n', [x y]');
    fclose(fid);
    [rc, out] = system(sprintf('"%s" fit --degree 2 --delay 0 --creep none "%s" 2>&1', ...
                               ctx.cli, file));
    said = regexp(out, ['the drive has (\d+) reversals inside its range \(minor loops\): f0 ' ...
                        'of --degree 2 is biased'], 'tokens', 'once');
    lastwarn('');
    hyst_fit(x, y, 'degree', 2, 'delay', 0, 'creep', 'none');
    [msg, id] = lastwarn();
    warned = strcmp(id, 'hyst:minor_loops');
    check(rc == 0 && warned == ~isempty(said) && warned == minor, ...
          'minor loops %d: hyst_fit warned %s "%s", hyst fit (%d) "%s"', minor, id, msg, rc, out);
    if minor
      n = regexp(msg, ['^hyst_fit: x has (\d+) reversals inside its range \(minor loops\): ' ...
                       'f0 of degree 2 is biased'], 'tokens', 'once');
      check(~isempty(n) && str2double(n{1}) == str2double(said{1}) && str2double(n{1}) == 9, ...
            'hyst_fit "%s", hyst fit "%s"', msg, out);
    end
    lastwarn('');
    hyst_fit(x, y, 'kind', 'everett', 'degree', 2, 'delay', 0, 'creep', 'none');
    [msg, id] = lastwarn();
    check(~strcmp(id, 'hyst:minor_loops'), 'kind everett warned: %s', msg);
    % the degree chosen among f0 alone ('kind', 'poly'; hyst fit --kind tcm)
    [rc, out] = system(sprintf('"%s" fit --kind tcm --creep none "%s" 2>&1', ctx.cli, file));
    said = regexp(out, ['the drive has (\d+) reversals inside its range \(minor loops\): f0 ' ...
                        'of every degree is biased'], 'tokens', 'once');
    lastwarn('');
    s = warning('off', 'hyst:excitation');
    hyst_fit(x, y, 'kind', 'poly', 'creep', 'none');
    warning(s);
    [msg, id] = lastwarn();
    warned = strcmp(id, 'hyst:minor_loops');
    check(rc == 0 && warned == ~isempty(said) && warned == minor && (~minor || ...
          ~isempty(regexp(msg, ['^hyst_fit: x has 9 reversals inside its range \(minor loops\): ' ...
                                'f0 of every degree is biased.*leave out ''kind'' to let ' ...
                                'hyst_fit compare E too'], 'once'))), ...
          'kind poly, minor loops %d: hyst_fit warned %s "%s", hyst fit (%d) "%s"', minor, id, ...
          msg, rc, out);
    lastwarn('');
    hyst_fit(x, y, 'creep', 'none');
    [msg, id] = lastwarn();
    check(~strcmp(id, 'hyst:minor_loops'), 'the choice among every kind warned: %s', msg);
  end
end

function t_fit_writes_e_of_the_width_as_f0(ctx)
  % the paper's plant driven with minor loops: E of t-degree 0 is chosen (f0's
  % estimator is biased there) and, being the symmetric model, written as
  % f0 (method 'branches'), as hyst fit writes it: the same model file
  legs = {0:0.25:39.75, 40:-0.25:0.25, 0:0.25:29.75, 30:-0.25:10.25, 10:0.25:24.75, ...
          25:-0.25:15.25, 15:-0.25:0.25};
  x = [repmat([legs{:}]', 4, 1); 0];
  y = hyst_sim(paper_f0(), x) + 0.005 * (mod((1:numel(x))' * 0.6180339887, 1) - 0.5);
  f = hyst_fit(x, y);
  chosen = f.candidates([f.candidates.chosen]);
  check(strcmp(chosen.kind, 'everett') && chosen.t_degree == 0 && ~isfield(f, 'kind') && ...
        strcmp(f.method, 'branches') && f.everett.t_degree == 0 && f.degree == 3, ...
        'chosen %s t-degree %d, written as method %s', chosen.kind, chosen.t_degree, f.method);
  e = struct('kind', 'everett', 'degree', 3, 'lo', f.lo, 'hi', f.hi, 'y_lo', f.everett.y_lo, ...
             'terms', f.everett.terms);
  check(max(abs(hyst_sim(f, x) - hyst_sim(e, x))) < 1e-9, 'f0 and E predict differently');
  file = fullfile(ctx.tmp, 'width.txt');
  fid = fopen(file, 'w');
  fprintf(fid, '%.17g %.17g\n', [x y]');
  fclose(fid);
  cli_file = fullfile(ctx.tmp, 'width_cli.hyst');
  out = run_cli(ctx, ['fit --save "' cli_file '" "' file '"']);
  check(~isempty(strfind(out, '# written as kind poly: E of t-degree 0 is the symmetric model')), ...
        'hyst fit did not write f0: %s', out);
  oct_file = fullfile(ctx.tmp, 'width_oct.hyst');
  hyst_model_save(oct_file, f);
  check(strcmp(fileread(oct_file), fileread(cli_file)), 'model files differ:\n%s\n%s', ...
        fileread(oct_file), fileread(cli_file));
  % 'method', 'branches': that fit of kind poly at a given degree, as hyst fit
  % --method branches writes it, with no warning of minor loops
  lastwarn('');
  b = hyst_fit(x, y, 'degree', 3, 'method', 'branches');
  [msg, id] = lastwarn();
  check(~strcmp(id, 'hyst:minor_loops'), 'method branches warned: %s', msg);
  run_cli(ctx, ['fit --degree 3 --method branches --save "' cli_file '" "' file '"']);
  hyst_model_save(oct_file, b);
  check(strcmp(b.method, 'branches') && strcmp(fileread(oct_file), fileread(cli_file)), ...
        'method branches: model files differ:\n%s\n%s', fileread(oct_file), fileread(cli_file));
  lastwarn('');
  hyst_fit(x, y, 'degree', 3);
  [msg, id] = lastwarn();
  check(strcmp(id, 'hyst:minor_loops') && ~isempty(strfind(msg, 'or fit ''method'', ''branches''')), ...
        'the joint estimator on minor loops: %s', msg);
  far = @() hyst_fit(x + 1e6, y, 'degree', 3, 'method', 'branches');
  expect_error('hyst:usage', far);
  msg = error_message(far);
  check(~isempty(strfind(msg, 'gives no f0 in powers of x')), 'far from 0: %s', msg);
  expect_error('hyst:usage', @() hyst_fit(x, y, 'degree', 5, 'method', 'branches'));
end

function t_fit_widens_symmetric_kinds_as_cli(ctx)
  % f0 a polynomial and a spline, on a record whose last third goes past the
  % first two thirds' peaks (triangles of growing amplitude on Eq. 20): the
  % widened candidate the tool chooses, fitted on its domain, the range it
  % was identified on saved; the model file the tool's, byte for byte
  x = [];
  for p = 8:4:40
    x = [x, 0:0.1:p - 0.05, p:-0.1:0.05];
  end
  x = [x(:); 0];
  y = hyst_sim(paper_f0(), x);
  n = floor(2 * numel(x) / 3);
  rec = fullfile(ctx.tmp, 'widen_rec.txt');
  fid = fopen(rec, 'w');
  fprintf(fid, '%.17g %.17g\n', [x(1:n) y(1:n)]');
  fclose(fid);
  cli_file = fullfile(ctx.tmp, 'widen_cli.hyst');
  oct_file = fullfile(ctx.tmp, 'widen_oct.hyst');
  kinds = {'tcm', 'poly'; 'spline', 'spline'};
  for k = 1:size(kinds, 1)
    run_cli(ctx, sprintf('fit --kind %s --creep none --delay 0 --save "%s" "%s" 2>&1', ...
                         kinds{k, 1}, cli_file, rec));
    f = hyst_fit(x(1:n), y(1:n), 'kind', kinds{k, 2}, 'degree', [], 'delay', 0, 'creep', 'none');
    hyst_model_save(oct_file, f);
    check(strcmp(fileread(oct_file), fileread(cli_file)), ...
          '%s: hyst_fit differs from hyst fit:\n%s\n%s', kinds{k, 2}, fileread(oct_file), ...
          fileread(cli_file));
    check(isfield(f, 'identified') && isequal(f.identified, [min(x(1:n)) max(x(1:n))]) && ...
          f.hi > max(x(1:n)), '%s: not widened: hi %g', kinds{k, 2}, f.hi);
  end
end

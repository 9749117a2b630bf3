% SPDX-License-Identifier: MIT
function model = hyst_model_load(file)
% HYST_MODEL_LOAD  Reads a model written by HYST_MODEL_SAVE.
%   MODEL = HYST_MODEL_LOAD(FILE) returns a struct with fields coeffs (a row,
%   highest power first), lo, hi and delay (samples; 0 when the file has
%   none), for HYST_SIM and HYST_INV. FILE must be in
%   the format hyst-model-text 1 (docs/matlab.md): its first line is exactly
%   that; then lines 'key value...', blank lines and '#' comment lines; the
%   keys kind (poly), lo, hi, coeffs, each once, and optionally delay (the
%   output follows its input this many samples later; written by 'hyst fit
%   --save'). Anything else (another
%   format or version, an unknown or repeated key, a number that is not
%   finite) raises hyst:model_file naming the file and the line.
  [fid, msg] = fopen(file, 'r');
  if fid < 0
    error('hyst:model_file', 'hyst_model_load: %s: %s', file, msg);
  end
  text = fread(fid, Inf, '*char')';
  fclose(fid);
  lines = regexp(text, '\r?\n', 'split');
  if isempty(lines) || ~strcmp(strtrim(lines{1}), 'hyst-model-text 1')
    first = '';
    if ~isempty(lines)
      first = strtrim(lines{1});
    end
    error('hyst:model_file', ...
          'hyst_model_load: %s:1: ''%s'' is not ''hyst-model-text 1'' (another format or version)', ...
          file, first);
  end
  seen = struct();
  for k = 2:numel(lines)
    line = strtrim(lines{k});
    if isempty(line) || line(1) == '#'
      continue;
    end
    [key, rest] = strtok(line);
    where = sprintf('hyst_model_load: %s:%d', file, k);
    if ~any(strcmp(key, {'kind', 'lo', 'hi', 'coeffs', 'delay'}))
      error('hyst:model_file', '%s: unknown key ''%s''', where, key);
    end
    if isfield(seen, key)
      error('hyst:model_file', '%s: key ''%s'' given twice', where, key);
    end
    if strcmp(key, 'kind')
      if ~strcmp(strtrim(rest), 'poly')
        error('hyst:model_file', '%s: kind ''%s'' is not poly', where, strtrim(rest));
      end
      seen.kind = 'poly';
      continue;
    end
    words = strsplit(strtrim(rest));
    v = str2double(words);
    if isempty(rest) || any(~isfinite(v)) || (~strcmp(key, 'coeffs') && numel(v) ~= 1)
      error('hyst:model_file', '%s: %s needs %s finite number%s', where, key, ...
            ifelse_(strcmp(key, 'coeffs'), 'one or more', 'one'), ifelse_(strcmp(key, 'coeffs'), 's', ''));
    end
    if strcmp(key, 'delay') && (v < 0 || v ~= round(v))
      error('hyst:model_file', '%s: delay %g is not a whole number of samples', where, v);
    end
    seen.(key) = v;
  end
  for key = {'kind', 'lo', 'hi', 'coeffs'}
    if ~isfield(seen, key{1})
      error('hyst:model_file', 'hyst_model_load: %s: key ''%s'' is missing', file, key{1});
    end
  end
  delay = 0;
  if isfield(seen, 'delay')
    delay = seen.delay;
  end
  model = struct('coeffs', seen.coeffs, 'lo', seen.lo, 'hi', seen.hi, 'delay', delay);
end

function r = ifelse_(c, a, b)
  if c
    r = a;
  else
    r = b;
  end
end

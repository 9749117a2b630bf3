% SPDX-License-Identifier: MIT
function model = hyst_model_load(file)
% HYST_MODEL_LOAD  Reads a model written by HYST_MODEL_SAVE.
%   MODEL = HYST_MODEL_LOAD(FILE) returns a struct with fields coeffs (a row,
%   highest power first), lo, hi and delay (samples; 0 when the file has
%   none), for HYST_SIM and HYST_INV; for a file of kind everett (the
%   asymmetric kind) the fields kind ('everett'), lo, hi, y_lo, degree,
%   terms (a row) and delay, for HYST_SIM. FILE must be in
%   the format hyst-model-text 1 (docs/matlab.md): its first line is exactly
%   that; then lines 'key value...', blank lines and '#' comment lines; the
%   keys kind (poly or everett), lo, hi, each once, coeffs (kind poly) or
%   y_lo, degree (1..4) and terms (degree (degree + 1) / 2 numbers; kind
%   everett), and optionally delay (the output follows its input this many
%   samples later; written by 'hyst fit --save') and a creep term, the keys
%   creep_tau (1 to 4 time constants, samples, each at least 1) and
%   creep_weight (as many weights), both or neither: then MODEL also has the
%   fields creep_tau and creep_weight (rows), which HYST_SIM, HYST_INV,
%   HYST_MODEL_SAVE and HYST_HEADER take (docs/matlab.md, "Creep").
%   Anything else (another format or version, an unknown or repeated key, a
%   key of the other kind, a number that is not finite, a creep key alone or
%   of another length than the other) raises hyst:model_file naming the
%   file and the line (for the creep keys also the field, in the words of
%   the host tool's reader).
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
  lists = {'coeffs', 'terms'};     % keys of several numbers
  seen = struct();
  at = struct();                   % the line of each key
  for k = 2:numel(lines)
    line = strtrim(lines{k});
    if isempty(line) || line(1) == '#'
      continue;
    end
    [key, rest] = strtok(line);
    where = sprintf('hyst_model_load: %s:%d', file, k);
    if ~any(strcmp(key, {'kind', 'lo', 'hi', 'coeffs', 'delay', 'y_lo', 'degree', 'terms', ...
                         'creep_tau', 'creep_weight'}))
      error('hyst:model_file', '%s: unknown key ''%s''', where, key);
    end
    if isfield(seen, key)
      error('hyst:model_file', '%s: key ''%s'' given twice', where, key);
    end
    at.(key) = k;
    if strcmp(key, 'kind')
      if ~any(strcmp(strtrim(rest), {'poly', 'everett'}))
        error('hyst:model_file', '%s: kind ''%s'' is not poly or everett', where, strtrim(rest));
      end
      seen.kind = strtrim(rest);
      continue;
    end
    if any(strcmp(key, {'creep_tau', 'creep_weight'}))
      seen.(key) = creep_numbers(where, key, rest);
      continue;
    end
    words = strsplit(strtrim(rest));
    v = str2double(words);
    if isempty(rest) || any(~isfinite(v)) || (~any(strcmp(key, lists)) && numel(v) ~= 1)
      error('hyst:model_file', '%s: %s needs %s finite number%s', where, key, ...
            ifelse_(any(strcmp(key, lists)), 'one or more', 'one'), ifelse_(any(strcmp(key, lists)), 's', ''));
    end
    if strcmp(key, 'delay') && (v < 0 || v ~= round(v))
      error('hyst:model_file', '%s: delay %g is not a whole number of samples', where, v);
    end
    if strcmp(key, 'degree') && ~any(v == 1:4)
      error('hyst:model_file', '%s: degree %g is not a whole number 1..4', where, v);
    end
    seen.(key) = v;
  end
  if ~isfield(seen, 'kind')
    error('hyst:model_file', 'hyst_model_load: %s: key ''kind'' is missing', file);
  end
  if strcmp(seen.kind, 'everett')
    needs = {'lo', 'hi', 'y_lo', 'degree', 'terms'};
    refuses = {'coeffs'};
  else
    needs = {'lo', 'hi', 'coeffs'};
    refuses = {'y_lo', 'degree', 'terms'};
  end
  for key = refuses
    if isfield(seen, key{1})
      error('hyst:model_file', 'hyst_model_load: %s:%d: key ''%s'' is not a key of kind %s', ...
            file, at.(key{1}), key{1}, seen.kind);
    end
  end
  for key = needs
    if ~isfield(seen, key{1})
      error('hyst:model_file', 'hyst_model_load: %s: key ''%s'' is missing', file, key{1});
    end
  end
  % the creep term: both keys or neither, as many numbers in each (the host
  % tool's checks and words, after the model's keys)
  if isfield(seen, 'creep_tau') ~= isfield(seen, 'creep_weight')
    keys = {'creep_tau', 'creep_weight'};
    has = keys{1 + isfield(seen, 'creep_weight')};
    other = keys{2 - isfield(seen, 'creep_weight')};
    error('hyst:model_file', ...
          'hyst_model_load: %s:%d: field 1: %s needs %s too (creep: both or neither)', ...
          file, at.(has), has, other);
  end
  if isfield(seen, 'creep_tau') && numel(seen.creep_tau) ~= numel(seen.creep_weight)
    n_w = numel(seen.creep_weight);
    n_t = numel(seen.creep_tau);
    if n_w < n_t
      what = sprintf('%d is missing', n_w + 2);
    else
      what = sprintf('%d: one too many', n_t + 2);
    end
    error('hyst:model_file', ...
          'hyst_model_load: %s:%d: field %s: creep_weight needs %d numbers, one per creep_tau', ...
          file, at.creep_weight, what, n_t);
  end
  delay = 0;
  if isfield(seen, 'delay')
    delay = seen.delay;
  end
  if strcmp(seen.kind, 'poly')
    model = struct('coeffs', seen.coeffs, 'lo', seen.lo, 'hi', seen.hi, 'delay', delay);
  else
    if numel(seen.terms) ~= seen.degree * (seen.degree + 1) / 2
      error('hyst:model_file', 'hyst_model_load: %s:%d: terms needs %d numbers for degree %d, not %d', ...
            file, at.terms, seen.degree * (seen.degree + 1) / 2, seen.degree, numel(seen.terms));
    end
    model = struct('kind', 'everett', 'lo', seen.lo, 'hi', seen.hi, 'y_lo', seen.y_lo, ...
                   'degree', seen.degree, 'terms', seen.terms, 'delay', delay);
  end
  if isfield(seen, 'creep_tau')
    model.creep_tau = seen.creep_tau;
    model.creep_weight = seen.creep_weight;
  end
end

function v = creep_numbers(where, key, rest)
% The numbers of a creep_tau or creep_weight line, checked as the host
% tool's reader checks them (tools/cli/model_file.c), with its words.
  words = strsplit(strtrim(rest));
  if isempty(strtrim(rest))
    words = {};
  end
  needs = sprintf('%s needs 1 to 4 numbers (one per creep term)', key);
  if isempty(words)
    error('hyst:model_file', '%s: field 2 is missing: %s', where, needs);
  end
  if numel(words) > 4
    error('hyst:model_file', '%s: field 6: one too many: %s', where, needs);
  end
  v = str2double(words);
  for i = 1:numel(words)
    if ~isfinite(v(i))
      error('hyst:model_file', '%s: field %d: ''%s'' is not a finite number', where, i + 1, ...
            words{i});
    end
    if strcmp(key, 'creep_tau') && ~(v(i) >= 1)
      error('hyst:model_file', ...
            '%s: field %d: ''%s'' is not a time constant of at least 1 sample', where, i + 1, ...
            words{i});
    end
  end
end

function r = ifelse_(c, a, b)
  if c
    r = a;
  else
    r = b;
  end
end

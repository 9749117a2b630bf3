% SPDX-License-Identifier: MIT
function hyst_model_save(file, model)
% HYST_MODEL_SAVE  Writes a model (f0 and its domain) to a text file.
%   HYST_MODEL_SAVE(FILE, MODEL) writes MODEL.coeffs (highest power first),
%   MODEL.lo and MODEL.hi (and MODEL.delay, samples, when it is not 0) in
%   the format hyst-model-text 1 (docs/matlab.md):
%
%     hyst-model-text 1
%     # ... comment lines
%     kind poly
%     lo 0
%     hi 40
%     coeffs -6.1875999999999998e-06 0.0011949 0.086443999999999993 0.58516999999999997
%
%   Numbers are written with 17 significant digits, so HYST_MODEL_LOAD gives
%   the same doubles back. The file is not checked against the library:
%   HYST_SIM does that.
  [c, lo, hi] = hyst_model_parts(model, 'hyst_model_save');
  if ~ischar(file)
    error('hyst:usage', 'hyst_model_save: FILE is a file name');
  end
  if isempty(c) || ~isscalar(lo) || ~isscalar(hi) || ~all(isfinite([c lo hi]))
    error('hyst:usage', 'hyst_model_save: coeffs, lo and hi must be finite numbers');
  end
  [fid, msg] = fopen(file, 'w');
  if fid < 0
    error('hyst:model_file', 'hyst_model_save: %s: %s', file, msg);
  end
  fprintf(fid, 'hyst-model-text 1\n');
  fprintf(fid, '# hyst model: f0 on [lo, hi], coefficients highest power first (docs/matlab.md)\n');
  fprintf(fid, 'kind poly\n');
  fprintf(fid, 'lo %.17g\nhi %.17g\n', lo, hi);
  if isstruct(model) && isfield(model, 'delay') && model.delay ~= 0
    fprintf(fid, 'delay %d\n', model.delay);
  end
  fprintf(fid, 'coeffs');
  fprintf(fid, ' %.17g', c);
  fprintf(fid, '\n');
  if fclose(fid) ~= 0
    error('hyst:model_file', 'hyst_model_save: %s: cannot write', file);
  end
end

% SPDX-License-Identifier: MIT
function model = hyst_model_load(file)
% HYST_MODEL_LOAD  Reads a model written by HYST_MODEL_SAVE.
%   MODEL = HYST_MODEL_LOAD(FILE) returns a struct with fields coeffs (a row,
%   highest power first), lo, hi and delay (samples; 0 when the file has
%   none), for HYST_SIM and HYST_INV; for a file of kind everett (the
%   asymmetric kind) the fields kind ('everett'), lo, hi, y_lo, degree,
%   terms (a row) and delay, for HYST_SIM; of kind everett_grid kind, lo,
%   hi, y_lo, knots, weights and delay; of kind spline kind, lo, hi, values,
%   slopes (rows) and delay. FILE must be in
%   the format hyst-model-text 1 (docs/matlab.md): its first line is exactly
%   that; then lines 'key value...', blank lines and '#' comment lines; the
%   keys kind (poly, everett, everett_grid or spline), lo, hi, each once,
%   coeffs (kind poly) or y_lo, degree (1..4) and terms (degree (degree +
%   1) / 2 numbers; kind everett), y_lo, knots and weights (kind
%   everett_grid) or values (2 to 33 numbers) and slopes (as many, each >=
%   0; kind spline), and optionally delay (the output follows its input this many
%   samples later; written by 'hyst fit --save') and a creep term, the keys
%   creep_tau (1 to 4 time constants, samples, each at least 1) and
%   creep_weight (as many weights), both or neither: then MODEL also has the
%   fields creep_tau and creep_weight (rows), which HYST_SIM, HYST_INV,
%   HYST_MODEL_SAVE and HYST_HEADER take (docs/matlab.md, "Creep"). A rate
%   term (keys rate_tau, rate_weight: docs/rate.md) gives MODEL the fields
%   rate_tau and rate_weight, which HYST_SIM and HYST_INV apply and
%   HYST_MODEL_SAVE and HYST_HEADER write. The
%   delay may hold a fraction of a sample (3.5); a file with the key
%   identified LO HI (the inputs' range the model was identified on, within
%   [lo, hi]) gives MODEL the field identified, [LO HI], which
%   HYST_MODEL_SAVE writes back.
%   Lines end at LF, CR LF or CR; numbers are decimal ('.' the decimal
%   mark); lo < hi. Anything else (another format or version, an unknown
%   or repeated key, a key of the other kind, a number that is not finite,
%   a creep key alone or of another length than the other) raises
%   hyst:model_file naming the file, the line and the field: the file is
%   read by the format's one reader in C (tools/model_text), in the words
%   of 'hyst sim --model' and of the Python package.
  [fid, msg] = fopen(file, 'r');
  if fid < 0
    error('hyst:model_file', 'hyst_model_load: %s: %s', file, msg);
  end
  % one byte more than the format allows, for the reader to refuse it
  bytes = fread(fid, 2^20 + 1, '*uint8')';
  fclose(fid);
  % the format's one reader (tools/model_text), the one 'hyst sim --model'
  % and the Python package call: hyst:model_file with its words
  try
    model = hyst_mex('model_parse', bytes, file);
  catch err
    % Octave puts the MEX file's name before its message, MATLAB does not
    error(err.identifier, 'hyst_model_load: %s', regexprep(err.message, '^hyst_mex: ', ''));
  end
end

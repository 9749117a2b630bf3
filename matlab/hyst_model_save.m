% SPDX-License-Identifier: MIT
function hyst_model_save(file, model)
% HYST_MODEL_SAVE  Writes a model (f0 and its domain, or an E) to a text file.
%   HYST_MODEL_SAVE(FILE, MODEL) writes MODEL.coeffs (highest power first),
%   MODEL.lo, MODEL.hi and MODEL.delay (samples, 0 without one) in the
%   format hyst-model-text 1 (docs/matlab.md), the text 'hyst fit --save'
%   writes (the format's one implementation, tools/model_text, in C):
%
%     hyst-model-text 1
%     # ... comment lines
%     kind poly
%     lo 0
%     hi 40
%     delay 0
%     coeffs -6.1875999999999998e-06 0.0011949 0.086443999999999993 0.58516999999999997
%
%   A model of kind 'everett' (HYST_SIM) is written with the keys kind
%   everett, lo, hi, y_lo, delay, degree and terms; one of kind
%   'everett_grid' with the keys kind everett_grid, lo, hi, y_lo, delay,
%   knots and weights; one of kind 'spline' with the keys kind spline, lo,
%   hi, delay, values and slopes. A model
%   with a creep term (fields creep_tau and creep_weight, 1 to 4 numbers
%   each) gets a comment line and the keys creep_tau and creep_weight after
%   its own, as the host tool writes them ('hyst fit --save'); one with a
%   rate term (fields rate_tau and rate_weight, scalars) the keys rate_tau
%   and rate_weight after those.
%   Numbers are written with 17 significant digits, so HYST_MODEL_LOAD gives
%   the same doubles back. The file is written whole or not at all (a
%   temporary file beside FILE, renamed to it; on failure removed and an
%   error hyst:model_file raised). The file is not checked against the library:
%   HYST_SIM does that.
  p = hyst_model_parts(model, 'hyst_model_save');
  if ~ischar(file)
    error('hyst:usage', 'hyst_model_save: FILE is a file name');
  end
  hyst_model_check(p, 'hyst_model_save');
  % the text of the format's one implementation (tools/model_text), the
  % one 'hyst fit --save' and the Python package write
  parts = hyst_text_parts(p);
  text = hyst_mex('model_write', parts{:}, p.identified, p.rate_tau, p.rate_weight);
  hyst_write_whole(file, text, 'hyst_model_save');
end

% SPDX-License-Identifier: MIT
function parts = hyst_text_parts(p)
% HYST_TEXT_PARTS  The model P (HYST_MODEL_PARTS) as the gateway's
%   model_write, header_open and header_table take it (the format's one
%   implementation, tools/model_text): kind, lo, hi, delay, coeffs, degree,
%   y_lo, terms, creep_tau, creep_weight; a grid's knots and weights, a
%   spline's values and slopes, in the places of coeffs and terms.
  switch p.kind
    case 'everett'
      parts = {'everett', p.lo, p.hi, p.delay, [], p.degree, p.y_lo, p.terms};
    case 'everett_grid'
      parts = {'everett_grid', p.lo, p.hi, p.delay, p.knots, 0, p.y_lo, p.weights};
    case 'spline'
      parts = {'spline', p.lo, p.hi, p.delay, p.values, 0, 0, p.slopes};
    otherwise
      parts = {'poly', p.lo, p.hi, p.delay, p.coeffs, 0, 0, []};
  end
  parts = [parts, {p.creep_tau, p.creep_weight}];
end

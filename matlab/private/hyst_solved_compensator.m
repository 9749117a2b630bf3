% SPDX-License-Identifier: MIT
function how = hyst_solved_compensator(kind)
% HYST_SOLVED_COMPENSATOR  How the compensator of a model of KIND solves
%   each sample when it has no table ('intervals' and 'rows' refused): for
%   kind everett_grid (hyst_curve_everett_grid_inverse()), in the host
%   tool's words; '' for the kinds with a tabulated compensator (poly,
%   everett, spline).
  switch kind
    case 'everett_grid'
      how = 'solves each branch in closed form';
    otherwise
      how = '';
  end
end

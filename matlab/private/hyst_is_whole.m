% SPDX-License-Identifier: MIT
function ok = hyst_is_whole(v)
% HYST_IS_WHOLE  V is one real, finite, whole number (of any numeric class).
  ok = isnumeric(v) && isreal(v) && isscalar(v) && isfinite(v) && v == floor(v);
end

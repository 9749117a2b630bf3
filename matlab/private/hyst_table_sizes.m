% SPDX-License-Identifier: MIT
function [intervals, rows] = hyst_table_sizes(intervals, rows, kind, caller, solved)
% HYST_TABLE_SIZES  The size of a tabulated compensator, checked before the
%   gateway allocates anything: INTERVALS 1..2^20 ([], the kind's default
%   HYST_INV_TABLE or HYST_EVERETT_INV_INTERVALS; 0 as well when SOLVED is
%   true: HYST_INV's exact, or solved, compensator) and ROWS 3..4096 (the
%   asymmetric kind's table only; [], the library's HYST_EVERETT_INV_ROWS).
%   Another value raises hyst:usage; returns the sizes the gateway takes
%   (ROWS the default for a polynomial f0, which does not use it).
  max_intervals = 2^20;
  config = hyst_mex('config');
  if isempty(intervals) && ~solved
    intervals = config.inv_table;
    if strcmp(kind, 'everett')
      intervals = config.everett_inv_intervals;
    end
  end
  if ~hyst_is_whole(intervals) || intervals < ~solved || intervals > max_intervals
    or_zero = '';
    if solved
      or_zero = ', or 0 for the exact compensator';
    end
    error('hyst:usage', ['%s: ''intervals'' must be a whole number in 1..%d (the table''s ' ...
                         'intervals)%s'], caller, max_intervals, or_zero);
  end
  intervals = double(intervals);
  if isempty(rows)
    rows = config.everett_inv_rows;
    return;
  end
  if ~strcmp(kind, 'everett')
    error('hyst:usage', ['%s: ''rows'' belongs to the asymmetric kind''s tabulated ' ...
                         'compensator; a polynomial''s or a spline''s f0^-1 has intervals ' ...
                         'only'], caller);
  end
  if intervals == 0
    error('hyst:usage', ['%s: ''rows'' needs ''intervals'' (1..%d): without it the ' ...
                         'compensator is solved, not tabulated'], caller, max_intervals);
  end
  if ~hyst_is_whole(rows) || rows < 3 || rows > 4096
    error('hyst:usage', '%s: ''rows'' must be a whole number in 3..4096 (default %d)', ...
          caller, config.everett_inv_rows);
  end
  rows = double(rows);
end

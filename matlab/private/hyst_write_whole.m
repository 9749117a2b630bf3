% SPDX-License-Identifier: MIT
function hyst_write_whole(file, text, caller)
% HYST_WRITE_WHOLE  TEXT into FILE whole or not at all: a temporary file in FILE's directory,
% renamed to FILE once written and closed; removed on failure.
  folder = fileparts(file);
  if isempty(folder)
    folder = '.';
  end
  tmp = tempname(folder);
  [fid, msg] = fopen(tmp, 'w');
  if fid < 0
    error('hyst:model_file', '%s: %s: %s', caller, file, msg);
  end
  written = fwrite(fid, text, 'char');
  if fclose(fid) ~= 0 || written ~= numel(text)
    delete(tmp);
    error('hyst:model_file', '%s: %s: cannot write', caller, file);
  end
  if exist('OCTAVE_VERSION', 'builtin')
    [status, msg] = rename(tmp, file);
    ok = status == 0;
  else
    [ok, msg] = movefile(tmp, file, 'f');
  end
  if ~ok
    delete(tmp);
    error('hyst:model_file', '%s: %s: %s', caller, file, msg);
  end
end

% SPDX-License-Identifier: MIT
function hyst_write_whole(file, text, caller)
% HYST_WRITE_WHOLE  TEXT into FILE whole or not at all: a temporary file in FILE's directory,
% renamed to FILE once written and closed; removed on failure. As 'hyst fit --save' writes: a
% symbolic link is written through (the file it names replaced, the link kept); a link to
% nothing, a directory, a device, a pipe or a socket is refused, left as it was (a rename would
% put a file in its place).
  file = regular_target(file, caller);
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

function file = regular_target(file, caller)
  if ~exist('OCTAVE_VERSION', 'builtin')  % MATLAB: no lstat; a folder at least
    if exist(file, 'dir')
      error('hyst:model_file', '%s: %s: is a directory: nothing written', caller, file);
    end
    return;
  end
  [st, err] = lstat(file);
  if err == 0 && S_ISLNK(st.mode)
    [target, status] = canonicalize_file_name(file);
    if status ~= 0
      error('hyst:model_file', '%s: %s: a symbolic link to nothing: nothing written', caller, ...
            file);
    end
    file = target;
  end
  [st, err] = stat(file);
  if err == 0 && S_ISDIR(st.mode)
    error('hyst:model_file', '%s: %s: is a directory: nothing written', caller, file);
  elseif err == 0 && ~S_ISREG(st.mode)
    error('hyst:model_file', ['%s: %s: not a regular file (a device, pipe or socket): ' ...
                              'nothing written'], caller, file);
  end
end

#!/bin/sh
# Every file pxflow opens, creates, renames or removes goes through hosts/io (the output plan and
# the input readers; docs/architecture.md), as every child process goes through
# hosts/core/guarded_child.cpp (dut_one_spawn_site): no file under HOSTS outside HOSTS/io may do
# it by other means. Usage: io_one_door.sh HOSTS. Exit 1 naming each line that does.
#
# Allowed outside io, each for its reason (file, then what it may call):
#   opencv/image_io.cpp   VideoCapture::open on a path hosts/io/video_file.cpp has checked and
#                         noted (the OpenCV module is io's decoder), and /dev/null to silence
#                         the decoders' stderr
#   dut/dut_link.cpp      open() of the serial port a user names in --dut NAME=serial:PATH: a
#                         device link, never read or written as a file
hosts=${1:?usage: io_one_door.sh HOSTS}
pattern='std::(i|o)?fstream|\b(fopen|freopen|fdopen|openat|creat|mkstemp|mkdtemp|mkostemp|tmpfile|rename|renameat|unlink|unlinkat|rmdir|truncate|imread|imwrite|elf_begin)[[:space:]]*\(|(^|[^_[:alnum:]])open[[:space:]]*\(|(fs|filesystem)::(remove|remove_all|rename|copy|copy_file|create_directory|create_directories|create_symlink|create_hard_link|resize_file|permissions)\b|VideoCapture|VideoWriter|(^|[^_[:alnum:]])::remove[[:space:]]*\('
hits=$(grep -rnE --include='*.cpp' --include='*.hpp' --include='*.c' --include='*.h' "$pattern" "$hosts" |
  grep -v "^$hosts/io/" |
  grep -vE '^[^:]+:[0-9]+:[[:space:]]*//' |
  grep -vE "^$hosts/opencv/image_io.cpp:[0-9]+:.*(VideoCapture|capture\.open\(|open\(\"/dev/null\")" |
  grep -vE "^$hosts/opencv/opencv_api.hpp:[0-9]+:.*VideoCapture" |
  grep -vE "^$hosts/dut/dut_link.cpp:[0-9]+:.*::open\(path\.c_str\(\), O_RDWR \| O_NOCTTY")
if [ -n "$hits" ]; then
  echo "$hits"
  echo "io_one_door: the lines above open, create, rename or remove a file outside hosts/io;"
  echo "read through hosts/io/input_file.hpp (or system_files.hpp) and write through an OutputPlan"
  exit 1
fi
echo "io_one_door: no file is opened outside hosts/io"

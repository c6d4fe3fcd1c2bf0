#!/usr/bin/env bash
# env-loader of search.launch's <machine> tags: roslaunch runs the nodes of a remote host through
# it. It sources the devel space of the checkout it lives in (the same path on every host), then
# runs the command it is given.
set -e
source "$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/devel/setup.bash"
exec "$@"

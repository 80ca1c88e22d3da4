"""Process facts of ROS nodes on this machine, for the soak script and the fault tests: a node's
pid (through its own XML-RPC getPid) and its resident memory (from /proc)."""
from xmlrpc.client import ServerProxy

import rosgraph


def node_pid(node, caller_id='/jetbot_rl_process_info'):
    """The process id of ROS node `node` (e.g. '/jetbot_env'), asked through its XML-RPC API."""
    uri = rosgraph.Master(caller_id).lookupNode(node)
    code, msg, pid = ServerProxy(uri).getPid(caller_id)
    if code != 1:
        raise RuntimeError('getPid of %s failed: %s' % (node, msg))
    return pid


def _status_kb(pid, key):
    with open('/proc/%d/status' % pid) as f:
        for line in f:
            if line.startswith(key + ':'):
                return int(line.split()[1])
    raise RuntimeError('no %s for pid %d' % (key, pid))


def rss_kb(pid):
    """Resident set [kB] of process `pid` (VmRSS)."""
    return _status_kb(pid, 'VmRSS')


def peak_rss_kb(pid):
    """Peak resident set [kB] of process `pid` (VmHWM)."""
    return _status_kb(pid, 'VmHWM')


def start_peak_rss(pid):
    """Resets the peak resident set of `pid` to its current one (Linux clear_refs 5), so that
    a later peak_rss_kb() shows the peak since now even below an earlier peak; returns the
    current resident set [kB], the baseline. Without the right to reset: the current peak."""
    try:
        with open('/proc/%d/clear_refs' % pid, 'w') as f:
            f.write('5')
        return rss_kb(pid)
    except OSError:
        return peak_rss_kb(pid)

"""Test tools that speak TCPROS by hand, to send a node bytes no ROS client library would.

FakePublisher registers a topic publisher with the master under its own caller id and XML-RPC
server, accepts the subscribers' connections and sends them raw message bytes. call_service_raw
looks a service up at the master and sends it a raw request. lying_length() patches the length
field of an array or string of a valid serialized message (found by serializing it twice).
"""
import io
import os
import socket
import struct
import threading
from xmlrpc.server import SimpleXMLRPCServer

import rosgraph
import rosgraph.network

BUFF_SIZE = 65536


def serialize(msg):
    """The serialized bytes of a genpy message (without the 4-byte frame length)."""
    buff = io.BytesIO()
    msg.serialize(buff)
    return buff.getvalue()


def length_offset(msg, grow):
    """Offset of an array or string field's 4-byte length in serialize(msg): the first byte that
    changes when `grow(copy)` adds one element (or character) to that field."""
    a = serialize(msg)
    grown = msg.__class__()
    grown.deserialize(a)
    grow(grown)
    b = serialize(grown)
    i = 0
    while i < len(a) and a[i] == b[i]:
        i += 1
    return i


def lying_length(msg, grow, element_size, lie=None):
    """serialize(msg) with the length of the field that `grow` grows set to `lie`; None: one
    element more than the bytes after the length field can hold. Returns (bytes, length)."""
    data = bytearray(serialize(msg))
    offset = length_offset(msg, grow)
    if lie is None:
        lie = (len(data) - offset - 4) // element_size + 1
    struct.pack_into('<I', data, offset, lie)
    return bytes(data), lie


def _send_frame(sock, payload):
    sock.sendall(struct.pack('<I', len(payload)) + payload)


def _recv_exactly(sock, n):
    chunks = []
    while n > 0:
        chunk = sock.recv(min(n, BUFF_SIZE))
        if not chunk:
            raise EOFError('connection closed with %d bytes still expected' % n)
        chunks.append(chunk)
        n -= len(chunk)
    return b''.join(chunks)


class FakePublisher(object):
    """A publisher of `topic` (type `msg_class`) registered with the master as `caller_id`, with
    its own XML-RPC and TCPROS servers; send() writes raw bytes to every connected subscriber.
    `on_connect` is called after each subscriber connection is set up."""

    def __init__(self, topic, msg_class, caller_id='/raw_tcpros_publisher', on_connect=None):
        self.topic = topic
        self.msg_class = msg_class
        self.caller_id = caller_id
        self.on_connect = on_connect
        self.lock = threading.Lock()
        self.subscribers = []  # (callerid, socket) after the handshake
        self.accepted = 0  # connections set up so far, including closed ones
        self.host = rosgraph.network.get_host_name()
        self.tcp = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.tcp.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.tcp.bind(('', 0))
        self.tcp.listen(5)
        self.tcp_port = self.tcp.getsockname()[1]
        self.xmlrpc = SimpleXMLRPCServer(('', 0), logRequests=False, allow_none=True)
        self.xmlrpc.register_function(self._request_topic, 'requestTopic')
        self.xmlrpc.register_function(lambda caller: [1, 'pid', os.getpid()], 'getPid')
        self.xmlrpc.register_function(lambda caller: [1, 'bus info', []], 'getBusInfo')
        self.xmlrpc.register_function(lambda caller, *args: [1, 'ignored', 0], 'shutdown')
        self.xmlrpc.register_function(lambda caller, *args: [1, 'ignored', 0], 'publisherUpdate')
        self.uri = 'http://%s:%d/' % (self.host, self.xmlrpc.server_address[1])
        self.closed = False
        threading.Thread(target=self.xmlrpc.serve_forever, daemon=True).start()
        threading.Thread(target=self._accept_loop, daemon=True).start()
        self.master = rosgraph.Master(caller_id)
        self.master.registerPublisher(topic, msg_class._type, self.uri)

    def _request_topic(self, caller_id, topic, protocols):
        if topic != self.topic:
            return [-1, 'not a publisher of %s' % topic, []]
        return [1, 'ready on %s:%d' % (self.host, self.tcp_port),
                ['TCPROS', self.host, self.tcp_port]]

    def _accept_loop(self):
        while not self.closed:
            try:
                sock, _ = self.tcp.accept()
            except OSError:
                return
            try:
                header = rosgraph.network.read_ros_handshake_header(sock, io.BytesIO(), BUFF_SIZE)
                rosgraph.network.write_ros_handshake_header(sock, {
                    'callerid': self.caller_id,
                    'topic': self.topic,
                    'type': self.msg_class._type,
                    'md5sum': self.msg_class._md5sum,
                    'message_definition': self.msg_class._full_text,
                    'latching': '0',
                })
            except Exception:  # a subscriber that went away: not ours to report
                sock.close()
                continue
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            with self.lock:
                self.subscribers.append((header.get('callerid', ''), sock))
                self.accepted += 1
            if self.on_connect:
                self.on_connect()

    def connected(self, caller_id=None):
        """Subscribers connected so far (those with `caller_id`, when given)."""
        with self.lock:
            return len([s for c, s in self.subscribers if caller_id is None or c == caller_id])

    def send(self, payload):
        """Sends `payload` (a message's bytes, as they are) to every subscriber; a subscriber
        that closed its connection is forgotten."""
        with self.lock:
            alive = []
            for caller, sock in self.subscribers:
                try:
                    _send_frame(sock, payload)
                    alive.append((caller, sock))
                except OSError:
                    sock.close()
            self.subscribers = alive

    def wait_until_dropped(self, caller_id, timeout):
        """Waits until the first connection of subscriber `caller_id` is closed by it; False
        after `timeout` [s]."""
        with self.lock:
            sock = next(s for c, s in self.subscribers if c == caller_id)
        sock.settimeout(timeout)
        try:
            while sock.recv(BUFF_SIZE):  # a subscriber sends nothing after its header
                pass
            return True
        except socket.timeout:
            return False
        except OSError:  # reset by the peer
            return True

    def close(self):
        self.closed = True
        try:
            self.master.unregisterPublisher(self.topic, self.uri)
        except Exception:  # the master may be gone at the end of a test
            pass
        self.xmlrpc.shutdown()
        self.xmlrpc.server_close()
        self.tcp.close()
        with self.lock:
            for _, sock in self.subscribers:
                sock.close()
            self.subscribers = []


class RawServiceClient(object):
    """A TCPROS connection to `service` (type `srv_class`), looked up at the master; call() sends
    raw request bytes and returns (ok, payload): the response bytes, or the error text."""

    def __init__(self, service, srv_class, caller_id='/raw_tcpros_client', persistent=True):
        uri = rosgraph.Master(caller_id).lookupService(service)
        host, port = uri[len('rosrpc://'):].rstrip('/').split(':')
        self.sock = socket.create_connection((host, int(port)), timeout=30.0)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        rosgraph.network.write_ros_handshake_header(self.sock, {
            'callerid': caller_id,
            'service': service,
            'md5sum': srv_class._md5sum,
            'persistent': '1' if persistent else '0',
        })
        self.header = rosgraph.network.read_ros_handshake_header(self.sock, io.BytesIO(),
                                                                 BUFF_SIZE)
        if 'error' in self.header:
            raise RuntimeError('service %s refused the connection: %s'
                               % (service, self.header['error']))

    def call(self, payload):
        self.send(payload)
        return self.receive()

    def send(self, payload):
        """Sends a request without waiting for its answer (see receive())."""
        _send_frame(self.sock, payload)

    def receive(self):
        """The answer to the request sent: (ok, response bytes or error text)."""
        ok = _recv_exactly(self.sock, 1)[0]
        (length,) = struct.unpack('<I', _recv_exactly(self.sock, 4))
        body = _recv_exactly(self.sock, length)
        return bool(ok), (body if ok else body.decode('utf-8', 'replace'))

    def close(self):
        self.sock.close()


class StalledSubscriber(object):
    """A subscriber of `topic` (type `msg_class`) that connects straight to the TCPROS server of
    publisher node `node`, sends its connection header and never reads anything: the publisher's
    socket to it fills up and stays full. `rcvbuf` [bytes] shrinks our receive buffer, so that it
    fills sooner."""

    def __init__(self, topic, msg_class, node, caller_id='/raw_stalled_subscriber', rcvbuf=None):
        from xmlrpc.client import ServerProxy
        uri = rosgraph.Master(caller_id).lookupNode(node)
        code, msg, protocol = ServerProxy(uri).requestTopic(caller_id, topic, [['TCPROS']])
        if code != 1:
            raise RuntimeError('requestTopic %s of %s failed: %s' % (topic, node, msg))
        _, host, port = protocol
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        if rcvbuf:
            self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, rcvbuf)
        self.sock.connect((host, port))
        self.publisher_port = port
        rosgraph.network.write_ros_handshake_header(self.sock, {
            'callerid': caller_id,
            'topic': topic,
            'type': msg_class._type,
            'md5sum': msg_class._md5sum,
            'tcp_nodelay': '1',
        })

    def unread_bytes(self):
        """Bytes waiting in our receive buffer (FIONREAD)."""
        import fcntl
        import termios
        count = bytearray(4)
        fcntl.ioctl(self.sock.fileno(), termios.FIONREAD, count)
        return struct.unpack('<i', bytes(count))[0]

    def unsent_bytes(self):
        """Bytes the publisher's socket to us holds unsent (its kernel send queue, from
        /proc/net/tcp; the publisher must run on this machine)."""
        ours = self.sock.getsockname()[1]
        for table in ('/proc/net/tcp', '/proc/net/tcp6'):
            try:
                with open(table) as f:
                    lines = f.readlines()[1:]
            except OSError:
                continue
            for line in lines:
                fields = line.split()
                local = int(fields[1].rsplit(':', 1)[1], 16)
                remote = int(fields[2].rsplit(':', 1)[1], 16)
                if (local, remote) == (self.publisher_port, ours):
                    return int(fields[4].split(':')[0], 16)  # tx_queue
        raise RuntimeError('no socket of the publisher to port %d' % ours)

    def read_seqs(self, last_seq, timeout):
        """Reads from now on, until a message with header.seq `last_seq` (or later) arrives: the
        publisher's connection header (once), then every message. Returns the header.seq of each
        message received (a message with a std_msgs/Header first), in order."""
        import time
        deadline = time.monotonic() + timeout
        self.sock.settimeout(max(0.1, timeout))
        if not getattr(self, '_header_read', False):
            (length,) = struct.unpack('<I', _recv_exactly(self.sock, 4))
            _recv_exactly(self.sock, length)
            self._header_read = True
        seqs = []
        while not seqs or seqs[-1] < last_seq:
            if time.monotonic() > deadline:
                raise RuntimeError('seq %d did not arrive within %.0f s (last %s)'
                                   % (last_seq, timeout, seqs[-1] if seqs else None))
            (length,) = struct.unpack('<I', _recv_exactly(self.sock, 4))
            payload = _recv_exactly(self.sock, length)
            seqs.append(struct.unpack_from('<I', payload)[0])
        return seqs

    def close(self):
        self.sock.close()

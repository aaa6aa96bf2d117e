// SPDX-License-Identifier: GPL-3.0-or-later
// The interactive pages' files: their text in the address's fragment (web-page.md,
// check-page.md), percent-encoded as encodeURIComponent writes UTF-8 text, where bytes that are
// not UTF-8 travel as %XX each, so that a malformed file reaches the reader, whose own message
// refuses it; a file opened from the reader's disk, and one saved as a download.
// Defines window.impulselabFiles = {encodeBytes, decodeFragment, utf8Text, download, opened}.
(() => {
  'use strict';
  const unreserved = /[A-Za-z0-9\-_.!~*'()]/;

  // Bytes as a fragment: the characters encodeURIComponent leaves alone as they are, %XX for every
  // other byte.
  function encodeBytes(bytes) {
    let text = '';
    for (const byte of bytes) {
      const c = String.fromCharCode(byte);
      text += byte < 0x80 && unreserved.test(c) ? c : '%' + byte.toString(16).toUpperCase().padStart(2, '0');
    }
    return text;
  }

  // The bytes a fragment stands for: %XX is a byte, any other character its UTF-8 bytes.
  function decodeFragment(fragment) {
    const bytes = [];
    const encoder = new TextEncoder();
    for (let i = 0; i < fragment.length; ++i) {
      const hex = fragment.slice(i + 1, i + 3);
      if (fragment[i] === '%' && /^[0-9A-Fa-f]{2}$/.test(hex)) {
        bytes.push(parseInt(hex, 16));
        i += 2;
      } else {
        const c = String.fromCodePoint(fragment.codePointAt(i));
        bytes.push(...encoder.encode(c));
        i += c.length - 1;
      }
    }
    return new Uint8Array(bytes);
  }

  // The text of @p bytes, or null when they are not UTF-8.
  function utf8Text(bytes) {
    try {
      return new TextDecoder('utf-8', {fatal: true}).decode(bytes);
    } catch (e) {
      return null;
    }
  }

  // Saves @p content (text or bytes) as the file @p name, of the MIME type @p type.
  function download(content, name, type) {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([content], {type}));
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  }

  // What the file input of @p event (its change) holds: the chosen file's text, or its bytes when
  // they are not UTF-8; null when none was chosen. The input is emptied, so that choosing the same
  // file again reads it again.
  async function opened(event) {
    const file = event.target.files[0];
    if (!file) {
      return null;
    }
    const bytes = new Uint8Array(await file.arrayBuffer());
    event.target.value = '';
    const text = utf8Text(bytes);
    return text !== null ? text : bytes;
  }

  window.impulselabFiles = {encodeBytes, decodeFragment, utf8Text, download, opened};
})();

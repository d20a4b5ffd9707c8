//! A small standard-alphabet base64 decoder for glTF `data:` URIs.

/// Decodes standard base64 (`A–Z a–z 0–9 + /`, optional `=` padding). ASCII whitespace is
/// skipped; any other character, or a dangling single character, gives `None`.
pub(crate) fn decode(text: &str) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(text.len() / 4 * 3);
    let mut accumulator: u32 = 0;
    let mut n_bits = 0;
    let mut padding = 0;
    for byte in text.bytes() {
        if byte.is_ascii_whitespace() {
            continue;
        }
        if byte == b'=' {
            padding += 1;
            continue;
        }
        if padding > 0 {
            return None; // Data after padding.
        }
        let value = match byte {
            b'A'..=b'Z' => byte - b'A',
            b'a'..=b'z' => byte - b'a' + 26,
            b'0'..=b'9' => byte - b'0' + 52,
            b'+' => 62,
            b'/' => 63,
            _ => return None,
        };
        accumulator = (accumulator << 6) | u32::from(value);
        n_bits += 6;
        if n_bits >= 8 {
            n_bits -= 8;
            out.push((accumulator >> n_bits) as u8);
            accumulator &= (1 << n_bits) - 1;
        }
    }
    // 6 leftover bits means one character of a final group: not valid base64.
    (n_bits < 6 && padding <= 2).then_some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rfc_4648_vectors() {
        let cases = [
            ("", ""),
            ("Zg==", "f"),
            ("Zm8=", "fo"),
            ("Zm9v", "foo"),
            ("Zm9vYg==", "foob"),
            ("Zm9vYmE=", "fooba"),
            ("Zm9vYmFy", "foobar"),
            ("Zm9vYmE", "fooba"),
        ];
        for (encoded, decoded) in cases {
            assert_eq!(decode(encoded).unwrap(), decoded.as_bytes(), "{encoded}");
        }
        assert_eq!(decode("AAECA/8=").unwrap(), vec![0, 1, 2, 3, 255]);
    }

    #[test]
    fn rejects_garbage() {
        assert_eq!(decode("Zm9v!"), None);
        assert_eq!(decode("Z"), None);
        assert_eq!(decode("Zg==Zg=="), None);
    }
}

//! Resolving buffer and image URIs: the GLB BIN chunk, `data:` URIs and the files the user
//! gave together with a .gltf. Nothing is ever fetched from the network or the file system.

use std::borrow::Cow;

use base64::Engine as _;

use super::error::GltfError;
use super::input::ImportFile;

/// The bytes behind a URI, borrowed from the given files where possible.
pub(crate) fn resolve<'a>(
    uri: &str,
    what: &'static str,
    index: usize,
    files: &[ImportFile<'a>],
) -> Result<Cow<'a, [u8]>, GltfError> {
    if let Some(rest) = uri.strip_prefix("data:") {
        return match (rest.split_once(";base64,"), rest.split_once(',')) {
            (Some((_, payload)), _) => base64::engine::general_purpose::STANDARD
                .decode(payload)
                .map(Cow::Owned)
                .map_err(|_| GltfError::BadDataUri { index }),
            (None, Some((_, payload))) => Ok(Cow::Owned(percent_decode(payload))),
            (None, None) => Err(GltfError::BadDataUri { index }),
        };
    }
    let error = |remote: bool| {
        let uri = uri.to_owned();
        if remote {
            GltfError::RemoteUri { what, index, uri }
        } else {
            GltfError::MissingFile { what, index, uri }
        }
    };
    if uri.contains("://") || uri.starts_with('/') {
        return Err(error(true));
    }
    let decoded = String::from_utf8_lossy(&percent_decode(uri)).into_owned();
    let wanted = file_name(&decoded);
    files
        .iter()
        .find(|file| file_name(file.name) == wanted)
        .map(|file| Cow::Borrowed(file.bytes))
        .ok_or_else(|| error(false))
}

/// The files a .gltf or .glb refers to (buffers and images outside the file, URIs decoded),
/// so a command-line tool can read them from beside it. Unreadable input gives none.
pub fn referenced_files(main: &[u8]) -> Vec<String> {
    let json = if main.starts_with(b"glTF") {
        match gltf::binary::Glb::from_slice(main) {
            Ok(glb) => glb.json.into_owned(),
            Err(_) => return Vec::new(),
        }
    } else {
        main.to_vec()
    };
    let Ok(value) = serde_json::from_slice::<serde_json::Value>(&json) else {
        return Vec::new();
    };
    ["buffers", "images"]
        .iter()
        .filter_map(|key| value.get(key)?.as_array())
        .flatten()
        .filter_map(|entry| entry.get("uri")?.as_str())
        .filter(|uri| !uri.starts_with("data:") && !uri.contains("://"))
        .map(|uri| String::from_utf8_lossy(&percent_decode(uri)).into_owned())
        .collect()
}

/// Each buffer's bytes, or why they are not available. A buffer that cannot be loaded is an
/// error only if an accessor that the import needs reads from it.
pub(crate) type Buffers<'a> = Vec<Result<Cow<'a, [u8]>, GltfError>>;

/// Loads every buffer (see [`Buffers`]).
pub(crate) fn load_buffers<'a>(
    document: &gltf::Document,
    blob: Option<Cow<'a, [u8]>>,
    files: &[ImportFile<'a>],
) -> Buffers<'a> {
    let mut blob = blob;
    document
        .buffers()
        .map(|buffer| match buffer.source() {
            gltf::buffer::Source::Bin => blob.take().ok_or(GltfError::NoBinaryData),
            gltf::buffer::Source::Uri(uri) => resolve(uri, "Buffer", buffer.index(), files),
        })
        .collect()
}

/// The last path component, so `textures/a.png` matches a dropped file named `a.png`.
fn file_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

/// Decodes `%XX` escapes (URIs in glTF are percent-encoded); invalid escapes stay as they are.
fn percent_decode(uri: &str) -> Vec<u8> {
    let bytes = uri.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut k = 0;
    while k < bytes.len() {
        let hex = bytes
            .get(k + 1..k + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[k], hex) {
            (b'%', Some(byte)) => {
                out.push(byte);
                k += 3;
            }
            (byte, _) => {
                out.push(byte);
                k += 1;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file<'a>(name: &'a str, bytes: &'a [u8]) -> ImportFile<'a> {
        ImportFile { name, bytes }
    }

    #[test]
    fn uris_resolve_to_given_files_only() {
        let files = [file("my model.bin", b"abcd"), file("dir/tex.png", b"png")];
        assert_eq!(
            resolve("my%20model.bin", "Buffer", 0, &files).unwrap(),
            &b"abcd"[..]
        );
        assert_eq!(
            resolve("textures/tex.png", "Image", 1, &files).unwrap(),
            &b"png"[..]
        );
        assert_eq!(
            resolve(
                "data:application/octet-stream;base64,AAEC",
                "Buffer",
                0,
                &[]
            )
            .unwrap(),
            &[0u8, 1, 2][..]
        );
        assert!(matches!(
            resolve("other.bin", "Buffer", 2, &files),
            Err(GltfError::MissingFile { index: 2, .. })
        ));
        assert!(matches!(
            resolve("https://example.com/a.bin", "Buffer", 0, &files),
            Err(GltfError::RemoteUri { .. })
        ));
        assert!(matches!(
            resolve("data:text/plain;base64,@@", "Buffer", 0, &files),
            Err(GltfError::BadDataUri { .. })
        ));
        assert_eq!(percent_decode("a%2Fb%zz%4"), b"a/b%zz%4");
        assert_eq!(
            resolve("data:application/gltf-buffer,%01A", "Buffer", 0, &[]).unwrap(),
            &[1u8, b'A'][..]
        );
        let gltf =
            br#"{"buffers":[{"uri":"a%20b.bin"},{"uri":"data:,x"}],"images":[{"uri":"t.png"}]}"#;
        assert_eq!(referenced_files(gltf), vec!["a b.bin", "t.png"]);
        assert!(referenced_files(b"glTF").is_empty());
    }
}

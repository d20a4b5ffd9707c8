//! Resolving buffer and image URIs: the GLB BIN chunk, `data:` URIs and the files the user
//! gave together with a .gltf. Nothing is ever fetched from the network or the file system.

use std::borrow::Cow;

use base64::Engine as _;

use super::error::GltfError;
use super::import::ImportFile;

/// The bytes behind a URI, borrowed from the given files where possible.
pub(crate) fn resolve<'a>(
    uri: &str,
    what: &'static str,
    index: usize,
    files: &[ImportFile<'a>],
) -> Result<Cow<'a, [u8]>, GltfError> {
    if let Some(rest) = uri.strip_prefix("data:") {
        let Some((_, payload)) = rest.split_once(";base64,") else {
            return Err(GltfError::BadDataUri { index });
        };
        return base64::engine::general_purpose::STANDARD
            .decode(payload)
            .map(Cow::Owned)
            .map_err(|_| GltfError::BadDataUri { index });
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
    let decoded = percent_decode(uri);
    let wanted = file_name(&decoded);
    files
        .iter()
        .find(|file| file_name(file.name) == wanted)
        .map(|file| Cow::Borrowed(file.bytes))
        .ok_or_else(|| error(false))
}

/// Loads every buffer, checking each against its declared length.
pub(crate) fn load_buffers<'a>(
    document: &gltf::Document,
    blob: Option<Cow<'a, [u8]>>,
    files: &[ImportFile<'a>],
) -> Result<Vec<Cow<'a, [u8]>>, GltfError> {
    let mut blob = blob;
    document
        .buffers()
        .map(|buffer| {
            let index = buffer.index();
            let data = match buffer.source() {
                gltf::buffer::Source::Bin => blob.take().unwrap_or_default(),
                gltf::buffer::Source::Uri(uri) => resolve(uri, "Buffer", index, files)?,
            };
            if data.len() < buffer.length() {
                return Err(GltfError::BufferTooShort {
                    index,
                    length: buffer.length(),
                });
            }
            Ok(data)
        })
        .collect()
}

/// The last path component, so `textures/a.png` matches a dropped file named `a.png`.
fn file_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

/// Decodes `%XX` escapes (URIs in glTF are percent-encoded); invalid escapes stay as they are.
fn percent_decode(uri: &str) -> String {
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
    String::from_utf8_lossy(&out).into_owned()
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
            resolve("data:text/plain,hello", "Buffer", 0, &files),
            Err(GltfError::BadDataUri { .. })
        ));
        assert_eq!(percent_decode("a%2Fb%zz%4"), "a/b%zz%4");
    }
}

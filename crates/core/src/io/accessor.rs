//! Reading accessors defensively: every component type, normalized integers
//! (`KHR_mesh_quantization`), byte strides, accessors without a buffer view, and sparse
//! substitution.
//!
//! Every range is checked against the real buffer before anything is allocated, and element
//! counts of accessors without data (which could claim 2^31 zeros) are capped by the caller,
//! so a hostile file cannot make the reader allocate more than its own size allows.

use gltf::accessor::DataType;

use super::error::GltfError;
use super::resources::Buffers;

/// Reads an accessor as `N` components per element, converted to `f64` (normalized integers
/// mapped to 0..1 or −1..1 as the spec says). `max_count` caps the element count.
pub(crate) fn read_f64<const N: usize>(
    accessor: &gltf::Accessor,
    buffers: &Buffers,
    max_count: usize,
) -> Result<Vec<[f64; N]>, GltfError> {
    let index = accessor.index();
    if accessor.dimensions().multiplicity() != N {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: match N {
                2 => "expected VEC2",
                3 => "expected VEC3",
                4 => "expected VEC4",
                _ => "unexpected element type",
            },
        });
    }
    let data_type = accessor.data_type();
    let normalized = accessor.normalized();
    let decode = move |bytes: &[u8]| -> [f64; N] {
        std::array::from_fn(|k| component(data_type, normalized, &bytes[k * data_type.size()..]))
    };
    read(
        accessor,
        buffers,
        max_count,
        N * data_type.size(),
        decode,
        [0.0; N],
    )
}

/// Reads a SCALAR accessor of unsigned integers (indices).
pub(crate) fn read_u32(
    accessor: &gltf::Accessor,
    buffers: &Buffers,
    max_count: usize,
) -> Result<Vec<u32>, GltfError> {
    let index = accessor.index();
    let data_type = accessor.data_type();
    if accessor.dimensions().multiplicity() != 1
        || !matches!(data_type, DataType::U8 | DataType::U16 | DataType::U32)
    {
        return Err(GltfError::UnsupportedAccessor {
            index,
            reason: "indices must be unsigned SCALAR integers",
        });
    }
    let decode = move |bytes: &[u8]| unsigned(data_type, bytes);
    read(accessor, buffers, max_count, data_type.size(), decode, 0)
}

/// Dense data (or zeros without a buffer view), then sparse substitution.
fn read<T: Copy>(
    accessor: &gltf::Accessor,
    buffers: &Buffers,
    max_count: usize,
    element_size: usize,
    decode: impl Fn(&[u8]) -> T,
    zero: T,
) -> Result<Vec<T>, GltfError> {
    let index = accessor.index();
    let count = accessor.count();
    let mut values = match accessor.view() {
        Some(view) => {
            let stride = view.stride().unwrap_or(element_size).max(element_size);
            let bytes = view_bytes(&view, accessor.offset(), buffers, index)?;
            check_span(count, stride, element_size, bytes.len(), index)?;
            (0..count)
                .map(|k| decode(&bytes[k * stride..k * stride + element_size]))
                .collect()
        }
        None if count > max_count => {
            return Err(GltfError::UnsupportedAccessor {
                index,
                reason: "it claims more elements than the import limits allow",
            });
        }
        None => vec![zero; count],
    };
    if let Some(sparse) = accessor.sparse() {
        let n = sparse.count();
        let indices = sparse.indices();
        let index_type = match indices.index_type() {
            gltf::accessor::sparse::IndexType::U8 => DataType::U8,
            gltf::accessor::sparse::IndexType::U16 => DataType::U16,
            gltf::accessor::sparse::IndexType::U32 => DataType::U32,
        };
        let index_bytes = view_bytes(&indices.view(), indices.offset(), buffers, index)?;
        check_span(
            n,
            index_type.size(),
            index_type.size(),
            index_bytes.len(),
            index,
        )?;
        let value_bytes = view_bytes(
            &sparse.values().view(),
            sparse.values().offset(),
            buffers,
            index,
        )?;
        check_span(n, element_size, element_size, value_bytes.len(), index)?;
        for k in 0..n {
            let target = unsigned(index_type, &index_bytes[k * index_type.size()..]) as usize;
            let Some(slot) = values.get_mut(target) else {
                return Err(GltfError::AccessorOutOfBounds { index });
            };
            *slot = decode(&value_bytes[k * element_size..(k + 1) * element_size]);
        }
    }
    Ok(values)
}

/// The bytes of a buffer view from `offset` on, checked against the buffer.
fn view_bytes<'b>(
    view: &gltf::buffer::View,
    offset: usize,
    buffers: &'b Buffers,
    accessor: usize,
) -> Result<&'b [u8], GltfError> {
    let out_of_bounds = GltfError::AccessorOutOfBounds { index: accessor };
    let buffer = match buffers.get(view.buffer().index()) {
        Some(Ok(buffer)) => buffer,
        Some(Err(error)) => return Err(error.clone()),
        None => return Err(out_of_bounds),
    };
    let end = view
        .offset()
        .checked_add(view.length())
        .ok_or(out_of_bounds.clone())?;
    buffer
        .get(view.offset()..end)
        .and_then(|bytes| bytes.get(offset..))
        .ok_or(out_of_bounds)
}

/// Whether `count` elements of `element_size` bytes at `stride` fit in `available` bytes.
fn check_span(
    count: usize,
    stride: usize,
    element_size: usize,
    available: usize,
    accessor: usize,
) -> Result<(), GltfError> {
    let needed = match count {
        0 => Some(0),
        _ => (count - 1)
            .checked_mul(stride)
            .and_then(|n| n.checked_add(element_size)),
    };
    match needed {
        Some(needed) if needed <= available => Ok(()),
        _ => Err(GltfError::AccessorOutOfBounds { index: accessor }),
    }
}

fn unsigned(data_type: DataType, b: &[u8]) -> u32 {
    match data_type {
        DataType::U8 => u32::from(b[0]),
        DataType::U16 => u32::from(u16::from_le_bytes([b[0], b[1]])),
        _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
    }
}

/// One component as `f64`; normalized integers as the glTF spec maps them.
fn component(data_type: DataType, normalized: bool, b: &[u8]) -> f64 {
    let (value, scale) = match data_type {
        DataType::I8 => (f64::from(b[0] as i8), 127.0),
        DataType::U8 => (f64::from(b[0]), 255.0),
        DataType::I16 => (f64::from(i16::from_le_bytes([b[0], b[1]])), 32767.0),
        DataType::U16 => (f64::from(u16::from_le_bytes([b[0], b[1]])), 65535.0),
        DataType::U32 => (f64::from(unsigned(DataType::U32, b)), 4294967295.0),
        DataType::F32 => return f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
    };
    if normalized {
        (value / scale).max(-1.0)
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalized_components_follow_the_spec() {
        assert_eq!(component(DataType::I8, true, &[0x81]), -1.0);
        assert_eq!(component(DataType::I8, true, &[0x80]), -1.0);
        assert_eq!(component(DataType::I8, true, &[127]), 1.0);
        assert_eq!(component(DataType::U8, true, &[255]), 1.0);
        assert_eq!(
            component(DataType::I16, false, &(-300i16).to_le_bytes()),
            -300.0
        );
        assert_eq!(component(DataType::U16, true, &[0xff, 0xff]), 1.0);
        assert_eq!(component(DataType::F32, true, &1.5f32.to_le_bytes()), 1.5);
    }

    #[test]
    fn spans_are_checked_without_overflow() {
        assert!(check_span(0, 12, 12, 0, 0).is_ok());
        assert!(check_span(2, 16, 12, 28, 0).is_ok());
        assert!(check_span(2, 16, 12, 27, 0).is_err());
        assert!(check_span(usize::MAX, 12, 12, 100, 0).is_err());
    }
}

//! Reads stored (uncompressed) entries back out of a ZIP archive by walking its central
//! directory, so that the packer can load the library from the archive as a master would.

use std::io;

const CENTRAL_HEADER_SIGNATURE: u32 = 0x0201_4b50;
const END_OF_CENTRAL_DIRECTORY_SIGNATURE: u32 = 0x0605_4b50;
const LOCAL_HEADER_LEN: usize = 30;

/// The bytes of the stored entry `path`.
pub fn read_entry(archive: &[u8], path: &str) -> io::Result<Vec<u8>> {
    let bad = |what: &str| io::Error::new(io::ErrorKind::InvalidData, format!("zip: {what}"));
    let end = (0..=archive.len().saturating_sub(22))
        .rev()
        .find(|&i| le32(archive, i) == Some(END_OF_CENTRAL_DIRECTORY_SIGNATURE))
        .ok_or_else(|| bad("no end of central directory"))?;
    let entries = le16(archive, end + 10).ok_or_else(|| bad("truncated end record"))? as usize;
    let mut at = le32(archive, end + 16).ok_or_else(|| bad("truncated end record"))? as usize;
    for _ in 0..entries {
        if le32(archive, at) != Some(CENTRAL_HEADER_SIGNATURE) {
            return Err(bad("bad central directory entry"));
        }
        let field = |offset: usize| {
            le16(archive, at + offset)
                .map(usize::from)
                .ok_or_else(|| bad("truncated"))
        };
        let method = field(10)?;
        let size = le32(archive, at + 20).ok_or_else(|| bad("truncated"))? as usize;
        let (name_len, extra_len, comment_len) = (field(28)?, field(30)?, field(32)?);
        let local = le32(archive, at + 42).ok_or_else(|| bad("truncated"))? as usize;
        let name = archive
            .get(at + 46..at + 46 + name_len)
            .ok_or_else(|| bad("truncated name"))?;
        if name == path.as_bytes() {
            if method != 0 {
                return Err(bad(&format!(
                    "{path} is compressed (method {method}); only stored entries are read"
                )));
            }
            let local_name = le16(archive, local + 26).ok_or_else(|| bad("truncated"))? as usize;
            let local_extra = le16(archive, local + 28).ok_or_else(|| bad("truncated"))? as usize;
            let start = local + LOCAL_HEADER_LEN + local_name + local_extra;
            return archive
                .get(start..start + size)
                .map(<[u8]>::to_vec)
                .ok_or_else(|| bad("truncated data"));
        }
        at += 46 + name_len + extra_len + comment_len;
    }
    Err(io::Error::new(
        io::ErrorKind::NotFound,
        format!("zip: no entry {path}"),
    ))
}

fn le16(b: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_le_bytes(b.get(at..at + 2)?.try_into().ok()?))
}

fn le32(b: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(at..at + 4)?.try_into().ok()?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::zip::{write_zip, Entry};

    #[test]
    fn entries_come_back_unchanged() {
        let entries = vec![
            Entry {
                path: "a.txt".into(),
                data: b"alpha".to_vec(),
            },
            Entry {
                path: "dir/b.bin".into(),
                data: (0..1000u32).map(|i| (i * 7) as u8).collect(),
            },
        ];
        let mut bytes = Vec::new();
        write_zip(&mut bytes, &entries).unwrap();
        for e in &entries {
            assert_eq!(read_entry(&bytes, &e.path).unwrap(), e.data);
        }
        assert_eq!(
            read_entry(&bytes, "missing").unwrap_err().kind(),
            io::ErrorKind::NotFound
        );
    }
}

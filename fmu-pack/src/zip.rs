//! A minimal ZIP writer: stored (uncompressed) entries, forward slashes, no links, which
//! is all an FMU archive needs (FMI 2.0 section 2.3: deflate or store).
//! Format: PKWARE APPNOTE 6.3, local file headers, central directory, end record.

use std::io::{self, Write};

const LOCAL_HEADER_SIGNATURE: u32 = 0x0403_4b50;
const CENTRAL_HEADER_SIGNATURE: u32 = 0x0201_4b50;
const END_OF_CENTRAL_DIRECTORY_SIGNATURE: u32 = 0x0605_4b50;
/// Version 2.0: the minimum that readers need for stored entries and folders.
const VERSION: u16 = 20;
/// 1980-01-01 00:00 in MS-DOS date/time: a fixed timestamp keeps the archive reproducible.
const DOS_DATE: u16 = (1 << 5) | 1;
const DOS_TIME: u16 = 0;

/// One entry to store: a path inside the archive (forward slashes) and its bytes.
pub struct Entry {
    pub path: String,
    pub data: Vec<u8>,
}

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320), as ZIP requires.
pub fn crc32(data: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &byte in data {
        crc ^= byte as u32;
        for _ in 0..8 {
            let mask = (crc & 1).wrapping_neg();
            crc = (crc >> 1) ^ (0xEDB8_8320 & mask);
        }
    }
    !crc
}

/// Writes the entries as a ZIP archive with stored entries.
pub fn write_zip(out: &mut impl Write, entries: &[Entry]) -> io::Result<()> {
    let mut offset = 0u32;
    let mut central = Vec::new();
    for entry in entries {
        let name = entry.path.as_bytes();
        let crc = crc32(&entry.data);
        let size =
            u32::try_from(entry.data.len()).map_err(|_| io::Error::other("entry over 4 GiB"))?;
        let mut local = Vec::with_capacity(30 + name.len());
        put32(&mut local, LOCAL_HEADER_SIGNATURE);
        common_fields(&mut local, crc, size, name.len());
        put16(&mut local, 0); // extra field length
        local.extend_from_slice(name);
        out.write_all(&local)?;
        out.write_all(&entry.data)?;

        put32(&mut central, CENTRAL_HEADER_SIGNATURE);
        put16(&mut central, VERSION); // version made by
        common_fields(&mut central, crc, size, name.len());
        put16(&mut central, 0); // extra field length
        put16(&mut central, 0); // comment length
        put16(&mut central, 0); // disk number
        put16(&mut central, 0); // internal attributes
        put32(&mut central, 0); // external attributes
        put32(&mut central, offset);
        central.extend_from_slice(name);
        offset += local.len() as u32 + size;
    }
    out.write_all(&central)?;
    let mut end = Vec::with_capacity(22);
    put32(&mut end, END_OF_CENTRAL_DIRECTORY_SIGNATURE);
    put16(&mut end, 0); // this disk
    put16(&mut end, 0); // disk with the central directory
    put16(&mut end, entries.len() as u16);
    put16(&mut end, entries.len() as u16);
    put32(&mut end, central.len() as u32);
    put32(&mut end, offset);
    put16(&mut end, 0); // comment length
    out.write_all(&end)
}

/// Fields shared by the local and the central header, from "version needed" to the name length.
fn common_fields(buf: &mut Vec<u8>, crc: u32, size: u32, name_len: usize) {
    put16(buf, VERSION); // version needed to extract
    put16(buf, 0); // flags
    put16(buf, 0); // method: stored
    put16(buf, DOS_TIME);
    put16(buf, DOS_DATE);
    put32(buf, crc);
    put32(buf, size); // compressed size
    put32(buf, size); // uncompressed size
    put16(buf, name_len as u16);
}

fn put16(buf: &mut Vec<u8>, v: u16) {
    buf.extend_from_slice(&v.to_le_bytes());
}

fn put32(buf: &mut Vec<u8>, v: u32) {
    buf.extend_from_slice(&v.to_le_bytes());
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::process::Command;

    #[test]
    fn crc32_of_the_standard_check_string() {
        // The CRC-32 check value of "123456789" (e.g. the CRC catalogue's CRC-32/ISO-HDLC).
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
        assert_eq!(crc32(b""), 0);
    }

    /// Python's zipfile, an independent reader, lists and verifies the archive.
    #[test]
    fn python_zipfile_reads_the_archive() {
        let entries = vec![
            Entry {
                path: "modelDescription.xml".into(),
                data: b"<xml/>".to_vec(),
            },
            Entry {
                path: "binaries/linux64/x.so".into(),
                data: (0..=255u8).cycle().take(70_000).collect(),
            },
            Entry {
                path: "resources/empty.txt".into(),
                data: Vec::new(),
            },
        ];
        let path = std::env::temp_dir().join(format!("fmu-pack-test-{}.zip", std::process::id()));
        let mut file = std::fs::File::create(&path).unwrap();
        write_zip(&mut file, &entries).unwrap();
        drop(file);
        let script = "import sys, zipfile\n\
                      z = zipfile.ZipFile(sys.argv[1])\n\
                      assert z.testzip() is None\n\
                      print(';'.join(f'{i.filename}:{i.file_size}' for i in z.infolist()))";
        let output = Command::new("python3")
            .arg("-c")
            .arg(script)
            .arg(&path)
            .output()
            .expect("python3 runs");
        std::fs::remove_file(&path).ok();
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        assert_eq!(
            String::from_utf8_lossy(&output.stdout).trim(),
            "modelDescription.xml:6;binaries/linux64/x.so:70000;resources/empty.txt:0"
        );
    }
}

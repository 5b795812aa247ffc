UPDATE signalo_db.vl_official_sign
SET img_width = 60 WHERE id = '4.51.1-a';

UPDATE signalo_db.vl_official_sign
SET img_width = 60 WHERE id = '4.51.1-b';

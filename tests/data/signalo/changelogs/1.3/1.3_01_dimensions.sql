UPDATE signalo_db.vl_official_sign
SET img_width = 171, img_height = 116 WHERE id = '5.00-2';

UPDATE signalo_db.vl_official_sign
SET img_width = 171, img_height = 116 WHERE id = '5.00-3';

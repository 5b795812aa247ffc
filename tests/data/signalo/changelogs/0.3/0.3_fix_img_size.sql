
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.49-l';
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.49-r';
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.50.1-r';
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.50.1-l';
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.50.3-l';
UPDATE signalo_db.vl_official_sign SET img_height = 60 WHERE id = '4.50.3-r';
UPDATE signalo_db.vl_official_sign SET img_width = 241 WHERE id = '4.49-l';
UPDATE signalo_db.vl_official_sign SET img_width = 241 WHERE id = '4.49-r';
UPDATE signalo_db.vl_official_sign SET img_width = 231 WHERE id = '4.50.1-r';
UPDATE signalo_db.vl_official_sign SET img_width = 231 WHERE id = '4.50.1-l';
UPDATE signalo_db.vl_official_sign SET img_width = 231 WHERE id = '4.50.3-l';
UPDATE signalo_db.vl_official_sign SET img_width = 231 WHERE id = '4.50.3-r';

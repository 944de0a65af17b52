!> Submodule support_layer of module b2b (b2b.f90): the bodies of the
!> private helpers all layers share (status and message handling, integer
!> and shape checks). Their interfaces and documentation are in b2b.f90:
!> separate module procedures, because gfortran gives a private procedure
!> contained in module b2b internal linkage, out of the submodules' reach.
submodule (b2b) support_layer
  implicit none

contains

  module procedure finish
    character(len=:), allocatable :: msg
    if (st == B2B_OK) then
      msg = ''
    else
      msg = c_chars(buf)
      if (len(msg) == 0) msg = procname // ': ' // b2b_strerror(int(st))
    end if
    if (present(errmsg)) errmsg = msg
    if (present(ierr)) then
      ierr = int(st)
    else if (st /= B2B_OK) then
      write (error_unit, '(a)') 'b2b error ' // trim(int_text(int(st))) // ': ' // msg
      error stop 'b2b: a call failed and no ierr argument was given to receive the status'
    end if
  end procedure

  module procedure finish_size
    call finish_text(procname, int(B2B_ERR_SIZE, c_int), procname // ': ' // argname // &
                     ' has shape (' // shape_text(got) // '), expected (' // &
                     shape_text(want) // ')', ierr, errmsg)
  end procedure

  module procedure finish_text
    character(kind=c_char) :: buf(B2B_ERRMSG_LEN)
    integer :: i
    buf = c_null_char
    do i = 1, min(len_trim(text), size(buf) - 1)
      buf(i) = text(i:i)
    end do
    call finish(procname, st, buf, ierr, errmsg)
  end procedure

  module procedure fits_c_int
    fits_c_int = v >= -huge(0_c_int) .and. v <= huge(0_c_int)
  end procedure

  module procedure check_ints
    integer :: i
    ok = .true.
    do i = 1, size(values)
      if (.not. fits_c_int(values(i))) then
        ok = .false.
        call finish_range(procname, trim(names(i)), values(i), ierr, errmsg)
        return
      end if
    end do
  end procedure

  module procedure check_int_array
    integer :: i
    ok = .true.
    do i = 1, size(a)
      if (.not. fits_c_int(a(i))) then
        ok = .false.
        call finish_range(procname, argname // '(' // trim(int_text(i)) // ')', a(i), ierr, &
                          errmsg)
        return
      end if
    end do
  end procedure

  module procedure optional_address
    p = c_null_ptr
    sh = -1
    if (present(addr)) then
      p = addr
      sh = actual_shape
    end if
  end procedure

  module procedure check_pair_optionals
    pk = c_null_ptr
    pt = c_null_ptr
    ldk = B2B_PAIR_NDOF
    ok = .false.
    if (kshape(1) >= 0) then
      if (kshape(1) < B2B_PAIR_NDOF .or. kshape(2) /= B2B_PAIR_NDOF) then
        call finish_text(procname, int(B2B_ERR_SIZE, c_int), procname // ': tangent has shape (' &
                         // shape_text(kshape) // '), expected (ldk,24) with ldk >= 24', ierr, &
                         errmsg)
        return
      end if
      call check_ints(procname, [character(len=15) :: 'size(tangent,1)'], [kshape(1)], ok, ierr, &
                      errmsg)
      if (.not. ok) return
      pk = tangent
      ldk = int(kshape(1), c_int)
    end if
    if (tshape(1) >= 0) then
      if (.not. shape_is(tshape, [3, 4])) then
        call finish_size(procname, 'end_tangents', tshape, [3, 4], ierr, errmsg)
        ok = .false.
        return
      end if
      pt = end_tangents
    end if
    ok = .true.
  end procedure

  module procedure check_pair_shapes
    ok = .false.
    if (.not. shape_is(shape(segments), [3, 2])) then
      call finish_size(procname, 'segments', shape(segments), [3, 2], ierr, errmsg)
      return
    end if
    call check_int_matrix(procname, 'segments', segments, ok, ierr, errmsg)
    if (.not. ok) return
    ok = .false.
    if (.not. shape_is(shape(X), [3, 8])) then
      call finish_size(procname, 'X', shape(X), [3, 8], ierr, errmsg)
      return
    end if
    if (.not. shape_is(shape(radii), [2])) then
      call finish_size(procname, 'radii', shape(radii), [2], ierr, errmsg)
      return
    end if
    ok = .true.
  end procedure

  module procedure check_int_matrix
    integer :: i, j
    ok = .true.
    do j = 1, size(a, 2)
      do i = 1, size(a, 1)
        if (.not. fits_c_int(a(i, j))) then
          ok = .false.
          call finish_range(procname, argname // '(' // trim(int_text(i)) // ',' // &
                            trim(int_text(j)) // ')', a(i, j), ierr, errmsg)
          return
        end if
      end do
    end do
  end procedure

  module procedure finish_range
    call finish_text(procname, int(B2B_ERR_RANGE, c_int), procname // ': ' // argname // &
                     ' = ' // trim(int_text(v)) // ' is beyond the range of a C int (+-' // &
                     trim(int_text(int(huge(0_c_int)))) // ')', ierr, errmsg)
  end procedure

  module procedure overlap
    integer(c_intptr_t) :: pa, pb, na, nb
    overlap = .false.
    if (size(a) == 0 .or. size(b) == 0) return
    pa = transfer(c_loc(a), pa)
    pb = transfer(c_loc(b), pb)
    na = size(a, kind=c_intptr_t) * (storage_size(a, kind=c_intptr_t) / 8)
    nb = size(b, kind=c_intptr_t) * (storage_size(b, kind=c_intptr_t) / 8)
    overlap = pa < pb + nb .and. pb < pa + na
  end procedure

  module procedure finish_alias
    call finish_text(procname, int(B2B_ERR_RANGE, c_int), procname // ': ' // outname // &
                     ' shares memory with ' // inname // ' (the same array?), which Fortran ' // &
                     'does not allow; pass a distinct array, or ' // inname // '=(h), ' // &
                     outname // '=h to update h in place', ierr, errmsg)
  end procedure

  module procedure fortran_terms
    character(len=:), allocatable :: msg
    integer :: i
    msg = replace_all(c_chars(buf), 'end_tangents is NULL', 'end_tangents is absent')
    if (len(hist) > 0) then
      msg = renumber(msg, hist // '[', hist // '(', ']', ')')
      msg = renumber(msg, 'but entry ', 'but ' // hist // '(', '', ')')
      msg = replace_all(msg, 'hist_len is ', 'size(' // hist // ') is ')
    end if
    buf = c_null_char
    do i = 1, min(len(msg), size(buf) - 1)
      buf(i) = msg(i:i)
    end do
  end procedure

  module procedure replace_all
    integer :: i, at
    out = ''
    i = 1
    do
      at = index(msg(i:), old)
      if (at == 0) exit
      out = out // msg(i:i + at - 2) // new
      i = i + at - 1 + len(old)
    end do
    out = out // msg(i:)
  end procedure

  module procedure renumber
    integer :: i, at, j, k, n, stat
    out = ''
    i = 1
    do
      at = index(msg(i:), key)
      if (at == 0) exit
      at = i + at - 1
      j = at + len(key)
      k = j
      do while (k <= len(msg))
        if (verify(msg(k:k), '0123456789') /= 0) exit
        k = k + 1
      end do
      stat = 1
      if (k > j .and. k - j < 10) then
        if (msg(k:min(k + len(close) - 1, len(msg))) == close) read (msg(j:k - 1), *, iostat=stat) n
      end if
      if (stat == 0) then
        out = out // msg(i:at - 1) // new_key // trim(int_text(n + 1)) // new_close
        i = k + len(close)
      else
        out = out // msg(i:j - 1)
        i = j
      end if
    end do
    out = out // msg(i:)
  end procedure

  module procedure shape_is
    shape_is = size(got) == size(want)
    if (shape_is) shape_is = all(got == want)
  end procedure

  module procedure shape_text
    integer :: i
    t = ''
    do i = 1, size(s)
      if (i > 1) t = t // ','
      t = t // trim(int_text(s(i)))
    end do
  end procedure

  module procedure int_text
    write (t, '(i0)') i
  end procedure

  module procedure c_flag
    c_flag = merge(1_c_int, 0_c_int, flag)
  end procedure

  module procedure blank_message
    buf = c_null_char
  end procedure

  module procedure c_chars
    integer :: n, i
    n = 0
    do while (n < size(buf))
      if (buf(n + 1) == c_null_char) exit
      n = n + 1
    end do
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = buf(i)
    end do
  end procedure

  module procedure c_string
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    if (.not. c_associated(p)) then
      s = ''
      return
    end if
    call c_f_pointer(p, chars, [huge(0)])
    n = 0
    do while (chars(n + 1) /= c_null_char)
      n = n + 1
    end do
    s = c_chars(chars(1:n))
  end procedure

end submodule support_layer

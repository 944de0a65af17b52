!> A lexical pass over a namelist file that records where every group and
!> every key is, by line.
!>
!> Why: a Fortran namelist READ reports a misspelt key without its line and
!> cannot say that a key is missing at all. This pass lets the reader name
!> the line of any key (or of the group, for a missing one) and reject
!> unknown groups and keys with the list of valid ones before reading.
module demo_nml_scan
  use demo_errors, only: str
  implicit none
  private

  integer, parameter :: word_len = 64

  type, public :: nml_key
    character(len=word_len) :: group = '', key = ''
    integer :: occurrence = 0, line = 0
  end type nml_key

  type, public :: nml_group
    character(len=word_len) :: name = ''
    integer :: occurrence = 0, line = 0
  end type nml_group

  type, public :: nml_index
    character(len=:), allocatable :: file
    integer :: n_groups = 0, n_keys = 0
    type(nml_group), allocatable :: groups(:)
    type(nml_key), allocatable :: keys(:)
  contains
    procedure :: count => index_count
    procedure :: group_line => index_group_line
    procedure :: key_line => index_key_line
    procedure :: has_key => index_has_key
  end type nml_index

  public :: nml_scan, lower

contains

  !> Scans file; ok = .false. with msg set on a lexical error (a key outside
  !> a group, a group not closed by '/').
  subroutine nml_scan(file, idx, ok, msg)
    character(len=*), intent(in) :: file
    type(nml_index), intent(out) :: idx
    logical, intent(out) :: ok
    character(len=:), allocatable, intent(out) :: msg
    integer :: u, ios, lineno, i, n, j, open_line
    character(len=1024) :: line
    character(len=word_len) :: current, word
    character(len=1) :: quote
    logical :: in_group

    allocate (idx%groups(16), idx%keys(64))
    idx%file = file
    ok = .true.
    msg = ''
    open (newunit=u, file=file, status='old', action='read', iostat=ios)
    if (ios /= 0) then
      ok = .false.
      msg = file // ': cannot open the scene file'
      return
    end if
    in_group = .false.
    current = ''
    open_line = 0
    quote = ' '
    lineno = 0
    do
      read (u, '(a)', iostat=ios) line
      if (ios /= 0) exit
      lineno = lineno + 1
      n = len_trim(line)
      i = 1
      do while (i <= n)
        associate (ch => line(i:i))
          if (quote /= ' ') then
            if (ch == quote) quote = ' '
            i = i + 1
          else if (ch == '''' .or. ch == '"') then
            quote = ch
            i = i + 1
          else if (ch == '!') then
            exit
          else if (ch == '&') then
            j = i + 1
            call read_word(line, j, word)
            if (in_group) then
              ok = .false.
              msg = file // ':' // str(lineno) // ': group &' // trim(word) // ' starts before &' &
                    // trim(current) // ' (line ' // str(open_line) // ') is closed: end each group with /'
              close (u)
              return
            end if
            in_group = .true.
            current = lower(word)
            open_line = lineno
            call add_group(idx, current, lineno)
            i = j
          else if (ch == '/') then
            in_group = .false.
            i = i + 1
          else if (is_letter(ch) .and. (i == 1 .or. .not. is_word_char(line(max(i - 1, 1):max(i - 1, 1))))) then
            j = i
            call read_word(line, j, word)
            ! a key is a word followed by an optional subscript and '='
            j = skip_blanks(line, j)
            if (j <= n) then
              if (line(j:j) == '(') then
                do while (j <= n)
                  if (line(j:j) == ')') exit
                  j = j + 1
                end do
                j = skip_blanks(line, j + 1)
              end if
            end if
            if (j <= n) then
              if (line(j:j) == '=') then
                if (.not. in_group) then
                  ok = .false.
                  msg = file // ':' // str(lineno) // ': key ' // trim(word) // ' outside a group: put it' &
                        // ' between &group and /'
                  close (u)
                  return
                end if
                call add_key(idx, current, lower(word), lineno)
              end if
            end if
            i = max(j, i + 1)
          else
            i = i + 1
          end if
        end associate
      end do
    end do
    close (u)
    if (in_group) then
      ok = .false.
      msg = file // ':' // str(open_line) // ': group &' // trim(current) // ' is not closed: end it with /'
    end if
  end subroutine nml_scan

  subroutine add_group(idx, name, lineno)
    type(nml_index), intent(inout) :: idx
    character(len=*), intent(in) :: name
    integer, intent(in) :: lineno
    type(nml_group), allocatable :: tmp(:)
    if (idx%n_groups == size(idx%groups)) then
      allocate (tmp(2 * size(idx%groups)))
      tmp(1:idx%n_groups) = idx%groups(1:idx%n_groups)
      call move_alloc(tmp, idx%groups)
    end if
    idx%n_groups = idx%n_groups + 1
    idx%groups(idx%n_groups)%name = name
    idx%groups(idx%n_groups)%line = lineno
    idx%groups(idx%n_groups)%occurrence = idx%count(name)
  end subroutine add_group

  subroutine add_key(idx, group, key, lineno)
    type(nml_index), intent(inout) :: idx
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: lineno
    type(nml_key), allocatable :: tmp(:)
    if (idx%n_keys == size(idx%keys)) then
      allocate (tmp(2 * size(idx%keys)))
      tmp(1:idx%n_keys) = idx%keys(1:idx%n_keys)
      call move_alloc(tmp, idx%keys)
    end if
    idx%n_keys = idx%n_keys + 1
    idx%keys(idx%n_keys)%group = group
    idx%keys(idx%n_keys)%key = key
    idx%keys(idx%n_keys)%line = lineno
    idx%keys(idx%n_keys)%occurrence = idx%count(group)
  end subroutine add_key

  !> Number of occurrences of a group.
  integer function index_count(idx, group) result(n)
    class(nml_index), intent(in) :: idx
    character(len=*), intent(in) :: group
    integer :: i
    n = 0
    do i = 1, idx%n_groups
      if (idx%groups(i)%name == lower(group)) n = n + 1
    end do
  end function index_count

  !> Line where occurrence k of a group starts (0 if absent).
  integer function index_group_line(idx, group, k) result(line)
    class(nml_index), intent(in) :: idx
    character(len=*), intent(in) :: group
    integer, intent(in) :: k
    integer :: i
    line = 0
    do i = 1, idx%n_groups
      if (idx%groups(i)%name == lower(group) .and. idx%groups(i)%occurrence == k) then
        line = idx%groups(i)%line
        return
      end if
    end do
  end function index_group_line

  !> Line of a key in occurrence k of a group; the group's line if the key is absent.
  integer function index_key_line(idx, group, k, key) result(line)
    class(nml_index), intent(in) :: idx
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: k
    integer :: i
    do i = 1, idx%n_keys
      if (idx%keys(i)%group == lower(group) .and. idx%keys(i)%occurrence == k &
          .and. idx%keys(i)%key == lower(key)) then
        line = idx%keys(i)%line
        return
      end if
    end do
    line = idx%group_line(group, k)
  end function index_key_line

  logical function index_has_key(idx, group, k, key) result(has)
    class(nml_index), intent(in) :: idx
    character(len=*), intent(in) :: group, key
    integer, intent(in) :: k
    integer :: i
    has = .false.
    do i = 1, idx%n_keys
      if (idx%keys(i)%group == lower(group) .and. idx%keys(i)%occurrence == k &
          .and. idx%keys(i)%key == lower(key)) then
        has = .true.
        return
      end if
    end do
  end function index_has_key

  subroutine read_word(line, j, word)
    character(len=*), intent(in) :: line
    integer, intent(inout) :: j
    character(len=*), intent(out) :: word
    integer :: j0
    j0 = j
    do while (j <= len_trim(line))
      if (.not. is_word_char(line(j:j))) exit
      j = j + 1
    end do
    word = line(j0:j - 1)
  end subroutine read_word

  integer function skip_blanks(line, j0) result(j)
    character(len=*), intent(in) :: line
    integer, intent(in) :: j0
    j = j0
    do while (j <= len_trim(line))
      if (line(j:j) /= ' ' .and. line(j:j) /= achar(9)) exit
      j = j + 1
    end do
  end function skip_blanks

  logical function is_letter(c)
    character(len=1), intent(in) :: c
    is_letter = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
  end function is_letter

  !> Characters of a name, and those that glue to a number or a logical
  !> (digits, '.', '%'), so that 1e5 or .true. never start a key.
  logical function is_word_char(c)
    character(len=1), intent(in) :: c
    is_word_char = is_letter(c) .or. (c >= '0' .and. c <= '9') .or. c == '_' .or. c == '%' .or. c == '.'
  end function is_word_char

  pure function lower(s) result(r)
    character(len=*), intent(in) :: s
    character(len=len(s)) :: r
    integer :: i
    r = s
    do i = 1, len(s)
      if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') r(i:i) = achar(iachar(s(i:i)) + 32)
    end do
  end function lower


end module demo_nml_scan
